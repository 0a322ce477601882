// The executor: records launches in program order, derives their dependencies from field
// privileges (read-after-write, write-after-read, write-after-write, per field and region),
// inserts a ghost copy before any launch that reads stale ghost values, and runs launches as
// soon as their inputs are ready — communication first (non-blocking MPI), so that copies
// overlap with independent tasks.
//
// Ghost values of a field are STALE after a write to its owned region (shared entities may have
// changed) or a layout change of its topology; they are VALID after a ghost copy or a write to
// the ghost region. Every rank records the same launches (SPMD), so every rank inserts the same
// copies; reductions start in program order so their collectives match across ranks.
#pragma once

#include "flecsi_lite/data/field_storage.hh"
#include "flecsi_lite/data/layout_listener.hh"
#include "flecsi_lite/data/privilege.hh"
#include "flecsi_lite/data/topology_base.hh"
#include "flecsi_lite/execution/launch.hh"
#include "flecsi_lite/execution/trace.hh"

#include <chrono>
#include <deque>
#include <map>

namespace flecsi_lite::execution {

/// One field argument of a launch and its privileges per region.
struct field_access {
  data::topology_base* topology;
  std::size_t field;
  data::field_storage_base* storage;
  privilege owned, ghost;
};

class executor final : public data::layout_listener {
public:
  static executor& instance();

  /// Records a launch; `start` runs when its dependencies (derived from `accesses`, plus
  /// `after`) are done. Returns the launch, for futures.
  launch_ptr record(std::string name, launch_kind kind, const std::vector<field_access>& accesses,
                    std::vector<launch_ptr> after, std::function<void(launch&)> start,
                    std::function<void()> finish = {});

  /// Runs launches until `target` is done.
  void wait(const launch& target);
  /// Runs every recorded launch.
  void wait_all();

  std::size_t pending() const { return queue_.size(); }
  std::uint64_t ghost_copies_started() const { return ghost_copies_; }

  /// Tracing: every completed launch is recorded while enabled (also with --trace FILE).
  void enable_tracing(bool on) { tracing_ = on; }
  const std::vector<trace_event>& trace() const { return trace_; }
  void clear_trace() { trace_.clear(); }

  void before_layout_change(std::uint64_t topology_id) override;
  void after_layout_change(std::uint64_t topology_id) override;
  void topology_destroyed(std::uint64_t topology_id) override;

private:
  executor();
  ~executor() override;

  // Dependency bookkeeping of one field on one topology instance.
  struct region_state {
    launch_ptr last_writer;
    std::vector<launch_ptr> readers;  // since the last write
  };
  struct field_state {
    region_state regions[2];  // owned, ghost
    bool ghosts_valid = false;
  };
  using field_key = std::pair<std::uint64_t, std::size_t>;  // (topology instance, field id)

  void add_dependencies(launch& l, field_state& state, region r, privilege p);
  launch_ptr record_ghost_copy(const field_access& a, field_state& state);
  bool ready(const launch& l) const;
  void begin(launch& l);
  void complete(launch& l);
  /// One scheduling round; false when nothing could progress without blocking.
  bool progress();
  void block_until_any_request();
  double now() const;

  std::deque<launch_ptr> queue_;          // recorded, not done, in program order
  std::map<field_key, field_state> fields_;
  std::uint64_t next_sequence_ = 0;
  std::uint64_t next_collective_recorded_ = 0, next_collective_started_ = 0;
  std::uint64_t ghost_copies_ = 0;
  bool tracing_ = false;
  bool inside_launch_ = false;
  std::vector<trace_event> trace_;
  std::chrono::steady_clock::time_point epoch_;
};

} // namespace flecsi_lite::execution
