// The state of an SPH run that the driver's control model acts on: settings, the particles (an
// ntree<D> with the SPH fields), the neighbour lists, the clock and the diagnostics. Apps derive
// their own state from it (problem parameters, output files).
#pragma once

#include "specialization/sph/model/conserved.hh"
#include "specialization/sph/model/neighbourhood.hh"
#include "specialization/sph/model/settings.hh"
#include "specialization/sph/model/timeline.hh"

#include "flecsi_lite/execution.hh"
#include "flecsi_lite/topology/ntree.hh"

#include <algorithm>
#include <chrono>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>

namespace flecsph::sph {

/// What the last gravity evaluation of this rank did (update_gravity, gravity.hh): interactions
/// of its targets and what the tree imported from other ranks.
struct gravity_record {
  std::uint64_t node_interactions = 0, particle_interactions = 0;
  std::size_t imported_nodes = 0, imported_particles = 0;
};

/// The balance of the distributions of a run: max over mean per rank of the particles and of the
/// work (list entries) of the search that follows each distribution. The work's reductions are
/// futures, settled at the next distribution or the report, so the step does not wait for them.
struct balance_record {
  std::uint64_t distributions = 0;
  double count_sum = 0, count_max = 0, work_sum = 0, work_max = 0;
  double pending_count = 0;
  flecsi_lite::future<double> pending_work_max, pending_work_total;  ///< valid while pending
  bool pending = false;

  void expect(double count_imbalance, flecsi_lite::future<double> most, flecsi_lite::future<double> total) {
    settle();
    pending_count = count_imbalance;
    pending_work_max = std::move(most);
    pending_work_total = std::move(total);
    pending = true;
  }
  void settle() {
    if (!pending) return;
    pending = false;
    const double mean = pending_work_total.get() / flecsi_lite::runtime::size();
    const double work_imbalance = mean > 0 ? pending_work_max.get() / mean : 1.0;
    ++distributions;
    count_sum += pending_count;
    work_sum += work_imbalance;
    count_max = std::max(count_max, pending_count);
    work_max = std::max(work_max, work_imbalance);
  }
  double count_mean() const { return distributions ? count_sum / double(distributions) : 1.0; }
  double work_mean() const { return distributions ? work_sum / double(distributions) : 1.0; }
};

/// Individual time steps: the active targets of a system step and their list entries.
struct active_count {
  double targets = 0, entries = 0;
};
struct active_count_sum {
  static active_count combine(const active_count& a, const active_count& b) {
    return {a.targets + b.targets, a.entries + b.entries};
  }
};

template<int D>
struct simulation {
  static constexpr int dimension = D;

  physics_settings physics;
  run_settings run;
  /// Periodic axes, fixed box, curve, ...; the driver sets the support from the physics.
  tree::ntree_config<D> tree_settings;

  std::unique_ptr<particle_tree<D>> particles;
  tracked_neighbourhood<D> neighbours{"sph neighbour lists"};

  double time = 0;
  double dt = 0;  ///< the step about to be taken
  long step = 0;
  bool finished = false;  ///< the last step reached end_time (or max_steps)
  /// Restored from a checkpoint: the state of the current step is complete (forces included).
  bool restarted = false;
  /// Distribute the particles at the next search (the first search of a run does).
  bool redistribute_next = false;
  /// Whether any particle of the run is a wall: the walls' accumulators (boundary_impulse,
  /// boundary_work) take memory and go to the checkpoints only then (the "walls" feature). The
  /// apps' control model finds it when the particles exist (find_walls); true until then, so that
  /// a driver of its own that creates walls keeps their accumulators.
  bool has_walls = true;
  /// True in "initialize" (the force evaluation at t = 0), false from its diagnostics on: what an
  /// action of the force_evaluation stage that belongs to t = 0 only tests.
  bool initializing = true;

  conserved_totals<D> initial_totals, totals;  ///< at the start, and at the last diagnostics
  long totals_step = -1;                       ///< step of `totals`
  std::uint64_t distributions = 0;             ///< calls of ntree::distribute()
  /// Over the distributions of the steps: particles that changed rank, and the bytes of all
  /// their fields (the traffic of the sample sort's all-to-all; the same on every rank).
  std::uint64_t moved_particles = 0;
  double moved_bytes = 0;
  std::uint64_t repeated_searches = 0;  ///< searches redone because h outgrew the reach
  std::uint64_t searches = 0;           ///< neighbour searches (the lists kept in between)
  double mean_neighbours = 0;           ///< at the last progress line, over all ranks
  std::chrono::steady_clock::time_point started;
  long started_step = 0;        ///< step when the cycle started
  double started_time = 0;      ///< simulation time then
  double elapsed = 0;           ///< wall seconds since the cycle started
  gravity_record last_gravity;  ///< self-gravity only
  balance_record balance;

  // Individual time steps only (time_bins.hh): the timeline, and the particles updated.
  timeline clock;
  double particle_updates = 0;  ///< fluid particles kicked, summed over the steps
  double woken = 0;             ///< particles the limiter woke

  // Between the actions of one step.
  /// Work a step left undone until every particle's values are read (gravity.hh: with individual
  /// time steps, the walk of the groups without active particles, whose potential only the
  /// totals and the files read); complete_deferred_fields(s) runs it once. Void after the drift.
  std::function<void()> deferred_fields;
  bool deferred_fields_read = false;  ///< this step's deferred work was run (was needed)
  int deferred_reads_in_a_row = 0;    ///< steps in a row whose deferred work was needed
  flecsi_lite::future<double> next_time_step;
  flecsi_lite::future<active_count> active_targets;  ///< individual time steps
  flecsi_lite::future<double> kicked;
};

/// Runs the work a step deferred (simulation::deferred_fields), before a reader of every particle's
/// values: the conserved totals, the output and the checkpoints. Collective where that work is.
template<int D>
void complete_deferred_fields(simulation<D>& s) {
  if (!s.deferred_fields) return;
  const std::function<void()> work = std::move(s.deferred_fields);
  s.deferred_fields = nullptr;
  s.deferred_fields_read = true;
  work();
}

}  // namespace flecsph::sph
