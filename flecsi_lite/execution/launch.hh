// One recorded unit of work of the executor: a task, a ghost copy, a ghost reduction (ghost
// values combined into their owners' values) or a reduction's collective,
// with the launches it must wait for. Communication launches post non-blocking MPI requests when
// they start and finish when those complete. A launch that throws FAILS; one that reads the
// results of a failed launch is CANCELLED (never runs) and fails with a message naming the
// failure; one merely ordered after it (write after write, write after read) runs.
#pragma once

#include <mpi.h>

#include <cstdint>
#include <exception>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace flecsi_lite::execution {

enum class launch_kind { task, ghost_copy, ghost_reduction, reduction };
enum class launch_state { recorded, in_flight, done, failed };

struct launch {
  std::uint64_t sequence = 0;  // program order
  std::string name;
  launch_kind kind = launch_kind::task;
  launch_state state = launch_state::recorded;
  std::vector<std::shared_ptr<launch>> dependencies;   // must be done: their results are read
  std::vector<std::shared_ptr<launch>> ordered_after;  // must be finished (done or failed)
  std::vector<std::shared_ptr<launch>> started;        // must have started (a copy has packed)
  std::vector<std::uint64_t> dependency_sequences;     // for the trace (critical path)
  std::function<void(launch&)> start;                  // runs the task, or packs and posts the requests
  std::function<void()> finish;                        // after the requests complete: unpack, combine
  std::vector<MPI_Request> requests;
  std::uint64_t collective_index = 0;  // reductions start in program order on every rank
  double begin_time = 0, end_time = 0;
  std::exception_ptr error;    // why it failed: its own exception, or a cancellation
  std::string failure_origin;  // the launch whose exception caused the failure
  std::string failure_reason;  // that exception's message

  bool communicates() const { return kind != launch_kind::task; }
  bool finished() const { return state == launch_state::done || state == launch_state::failed; }
};

using launch_ptr = std::shared_ptr<launch>;

}  // namespace flecsi_lite::execution
