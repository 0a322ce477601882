// What the executor ran and when: one event per launch, in completion order. Written as Chrome
// trace JSON (open in https://ui.perfetto.dev or chrome://tracing) with --trace FILE: a process
// per rank ("rank N"), tasks on track "compute", copies and collectives in flight on
// "communication" tracks; scripts/trace_summary.py reads it (overlap, idle time, critical path).
#pragma once

#include <cstdint>
#include <iosfwd>
#include <string>
#include <vector>

namespace flecsi_lite::execution {

struct trace_event {
  std::uint64_t sequence;  // program order of the launch
  std::string name;
  std::string kind;                         // "task", "ghost_copy", "reduction"
  double begin, end;                        // seconds since the executor started
  std::vector<std::uint64_t> dependencies;  // sequences of the launches it waited for
};

/// The track of each event: 0 for tasks (they never overlap), 1, 2, ... for communication (the
/// first track free when it starts).
std::vector<int> trace_tracks(const std::vector<trace_event>& events);

/// Writes the events of every rank (gathered to rank 0) as Chrome trace JSON. Collective.
void write_chrome_trace(const std::vector<trace_event>& events, std::ostream& out);

}  // namespace flecsi_lite::execution
