// The executor: records launches in program order, derives their dependencies from field
// privileges (read-after-write, write-after-read, write-after-write, per field and region),
// inserts a ghost copy before any launch that reads stale ghost values, and runs launches as
// soon as their inputs are ready — communication first (non-blocking MPI), so that copies
// overlap with independent tasks.
//
// A copy starts when its data is ready: once a field's ghosts have been read, every later write
// of its owned values is followed at once by a copy (recorded eagerly), so the messages travel
// while the tasks in between run. All the stale fields of one topology that a launch needs (or
// that one writer made stale) travel together, one message per peer. Long loops (forall) call
// poll() between chunks, so MPI advances while tasks run.
//
// A task that throws fails; launches that depend on it are cancelled; get() of their futures
// rethrows (the task's own exception, or "cancelled because ... failed"). On several ranks the
// others wait for the failed rank's messages, so a rank with a failure aborts the communicator
// (with the failure's message) rather than block or finalize.
//
// Ghost values of a field are STALE after a write to its owned region (shared entities may have
// changed) or a layout change of its topology; they are VALID after a ghost copy or a write to
// the ghost region. Every rank records the same launches (SPMD), so every rank inserts the same
// copies; reductions start in program order so their collectives match across ranks. A ghost
// reduction (reduce_ghosts.hh) sends ghost values back to their owners, combined there: it reads
// the ghost region and writes the owned one.
#pragma once

#include "flecsi_lite/data/field_storage.hh"
#include "flecsi_lite/data/layout_listener.hh"
#include "flecsi_lite/data/privilege.hh"
#include "flecsi_lite/data/topology_base.hh"
#include "flecsi_lite/execution/launch.hh"
#include "flecsi_lite/execution/trace.hh"

#include <chrono>
#include <cstddef>
#include <deque>
#include <functional>
#include <map>
#include <memory>
#include <set>

namespace flecsi_lite::execution {
namespace detail {
struct sent_ghost_values;
}

/// What this rank's ghost copies sent and received (messages to and from other ranks; a
/// periodic image of the rank's own entities is no message).
struct ghost_traffic {
  std::uint64_t messages_sent = 0, bytes_sent = 0;
  std::uint64_t messages_received = 0, bytes_received = 0;
};

/// A ghost reduction's combination of `values` (one element of the field each, as bytes) into
/// the owned entities `owned` (owned[i] takes values[i]) with the reduction's operation.
using combine_into_owned = std::function<void(const std::vector<std::size_t>& owned, const std::byte* values)>;

/// One field argument of a launch and its privileges per region; a tracked object is an access
/// with no topology and no storage (its privilege is the owned one, its ghost privilege na).
struct field_access {
  std::uint64_t instance;  // the topology's or the tracked object's instance_id()
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

  /// Records a ghost reduction of one field (reduce_ghosts.hh): after the launches recorded so
  /// far that write its ghosts, each ghost value is combined into its owner's value; the
  /// owners' values change (their ghosts are stale after it).
  launch_ptr record_ghost_reduction(const field_access& field, combine_into_owned combine);

  /// Runs launches until `target` is finished; rethrows its error when it failed.
  void wait(const launch& target);
  /// Runs every recorded launch; rethrows the first failure nobody has seen through a future.
  void wait_all();
  /// The field's ghosts may have been written outside tasks (host_view): its next ghost copy
  /// sends every value, not only those that changed since the last one.
  void forget_sent_values(std::uint64_t instance, std::size_t field);
  /// Between chunks of long loops inside a task: completes communication whose requests are done
  /// and posts copies that became ready. True while some communication is in flight.
  bool poll();
  /// Forgets the failures seen so far (a program that caught them on every rank and goes on).
  void forgive_failures() {
    failures_ = 0;
    unobserved_.clear();
  }

  std::size_t pending() const { return queue_.size(); }
  /// Whether some ghost copy or collective has posted requests that have not completed.
  bool communication_in_flight() const;
  /// Fields whose ghosts were copied (a copy of several fields counts each), and copy launches
  /// (each one message per peer).
  std::uint64_t ghost_copies_started() const { return ghost_copies_; }
  std::uint64_t ghost_updates_started() const { return ghost_updates_; }
  /// Messages and bytes of the ghost copies started so far (printed with the timers at exit).
  const ghost_traffic& traffic() const { return traffic_; }

  /// Tracing: every completed launch is recorded while enabled (also with --trace FILE).
  void enable_tracing(bool on) { tracing_ = on; }
  const std::vector<trace_event>& trace() const { return trace_; }
  void clear_trace() { trace_.clear(); }

  void before_layout_change(std::uint64_t topology_id) override;
  void after_layout_change(std::uint64_t topology_id) override;
  void topology_destroyed(std::uint64_t topology_id) override;
  void before_host_access(std::uint64_t) override { wait_all(); }

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
    bool ghosts_read = false;  // some launch has read the ghosts: copy eagerly after writes
    // The writer after which the last eager copy went out, until a launch reads the ghosts it
    // delivered; writers whose copy was overwritten unread get no eager copy again.
    std::string eager_after;
    std::set<std::string> copy_wasted_after;
    // What its copies last sent to each peer, and whether the peers' ghosts still hold it (no
    // launch recorded since the last copy writes the ghosts): a copy then sends only changes.
    std::shared_ptr<detail::sent_ghost_values> sent;
    bool receivers_hold_sent = false;
  };
  using field_key = std::pair<std::uint64_t, std::size_t>;  // (topology instance, field id)

  void add_dependencies(launch& l, field_state& state, region r, privilege p);
  /// One copy of the ghosts of `fields` (all on one topology): one message per peer.
  launch_ptr record_ghost_copy(const std::vector<const field_access*>& fields);
  /// Records one copy per topology for the stale fields among `accesses` that `wanted` selects.
  template<class Wanted>
  void record_ghost_copies(const std::vector<field_access>& accesses, Wanted wanted);
  bool ready(launch& l);
  void begin(const launch_ptr& l);
  void complete(launch& l);
  void fail(launch& l, std::exception_ptr error, const std::string& origin);
  void note(const launch& l);  // trace and timers
  void release(launch& l);     // drops what a finished launch no longer needs
  /// Completes the communication launches whose requests are done; true if any did.
  bool complete_arrived_communication();
  [[noreturn]] void abort_run() const;
  /// One scheduling round; false when nothing could progress without blocking.
  bool progress();
  void block_until_any_request();
  double now() const;

  std::deque<launch_ptr> queue_;  // recorded, not done, in program order
  std::map<field_key, field_state> fields_;
  std::uint64_t next_sequence_ = 0;
  std::uint64_t next_collective_recorded_ = 0, next_collective_started_ = 0;
  std::uint64_t ghost_copies_ = 0, ghost_updates_ = 0;
  ghost_traffic traffic_;
  bool tracing_ = false;
  bool inside_launch_ = false, polling_ = false;
  std::size_t failures_ = 0;            // failed launches (their own exception)
  std::vector<launch_ptr> unobserved_;  // failures no future's get() has reported
  std::string first_failure_;
  std::vector<trace_event> trace_;
  std::chrono::steady_clock::time_point epoch_;
};

}  // namespace flecsi_lite::execution
