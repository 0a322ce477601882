// Individual (block) time steps: each particle advances by 2^bin ticks of the timeline
// (timeline.hh), its bin the largest whose step its own criterion allows (Courant with the
// signal speed, acceleration), kick-drift-kick per particle as in GADGET-2 (Springel 2005, MNRAS
// 364, 1105, sec. 5) and SWIFT:
//   at the start of its step (tick b, length L):  v_half = v + L/2 a,  u_half = u + L/2 du
//   every system step (tick n to n'):           x += (n' - n) v_half for every fluid particle,
//                                                v, u predicted at n': v_half + (n' - b - L/2) a,
//                                                rho, h of the inactive ones drifted with div v
//   at its end b + L (active):                   density, forces; v = v_half + L/2 a_new
// The system step goes from now to the earliest end among the particles; only the particles that
// end there (the active ones) get density, velocity gradients and forces; the others are drifted
// and predicted, so the active ones see them at the current time. The time-step limiter (Saitoh
// & Makino 2009, ApJ 697, L99; SWIFT's --limiter) keeps every particle's bin at most
// log2(time_step_limiter) above the smallest among its neighbours: an active particle takes the
// smaller bin, an inactive one is woken, its step ending at the next multiple of the smaller step
// with its first kick shortened to the new length. Wall particles are active in every system step.
// Every decision is on integers of particle data (exact minima over ranks), so the results do not
// depend on the rank count.
#pragma once

#include "specialization/sph/model/neighbourhood.hh"
#include "specialization/sph/model/simulation.hh"
#include "specialization/sph/model/tasks.hh"
#include "specialization/sph/model/timeline.hh"
#include "specialization/sph/step/integrator.hh"

#include "specialization/physics/kernels.hh"

#include "flecsi_lite/execution.hh"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>

namespace flecsph::sph {

/// The bin walls carry: they never limit a neighbour.
inline constexpr std::int32_t wall_bin = timeline::bins;

/// All particles active at tick 0 (every step ends there), in the largest bin until their first
/// criterion is known.
template<int D>
void start_time_bins(wo<std::int32_t> time_bin, wo<std::int64_t> step_begin, wo<std::int64_t> step_end) {
  flecsi_lite::forall(
    time_bin.size(),
    [&](std::size_t a) {
      time_bin(a) = wall_bin;
      step_begin(a) = 0;
      step_end(a) = 0;
    },
    "sph::start_time_bins");
}

/// The targets whose step ends at tick `next`, for the pair tasks (neighbourhood::targets), and,
/// with balance = work (`work` present), their work: list length times how often the particle is
/// active (2^-bin of the span; the others keep theirs). Returns how many targets are active and
/// their list entries.
template<int D>
active_count select_active(typename tracked_neighbourhood<D>::template accessor<flecsi_lite::rw> neighbours,
                           std::int64_t next, ro<std::int64_t> step_end, ro<std::int32_t> time_bin, rw<double> work) {
  auto& n = *neighbours;
  active_count count;
  double* const weight = work.data();  // null without balance = work
  const auto pick = [&](const std::vector<std::uint32_t>& all, std::vector<std::uint32_t>& active) {
    active.clear();
    for (const std::uint32_t a : all) {
      if (step_end(a) != next) continue;
      active.push_back(a);
      const double entries = static_cast<double>(n.lists.count(a));
      if (weight) weight[a] = std::ldexp(entries, timeline::bins - time_bin(a));
      count.entries += entries;
    }
  };
  pick(n.interior, n.active_interior);
  pick(n.boundary, n.active_boundary);
  n.active_tick = next;
  count.targets = static_cast<double>(n.active_interior.size() + n.active_boundary.size());
  return count;
}

/// The first kick of the particles whose step starts now, the drift of every fluid particle to
/// `clock.next` and the prediction of v and u there (walls: their accumulators, as kick_drift).
template<int D>
void kick_drift_bins(timeline clock, tree::domain<D> space, bool adaptive_h, ro<particle_kind> kind, rw<vector<D>> x,
                     rw<vector<D>> v, rw<vector<D>> v_half, rw<double> u, rw<double> u_half, ro<vector<D>> acceleration,
                     ro<double> du_dt, ro<double> velocity_divergence, rw<double> rho, rw<double> h,
                     rw<vector<D>> impulse, rw<double> work, rw<double> drift, rw<std::int32_t> time_bin,
                     rw<std::int64_t> step_begin, rw<std::int64_t> step_end, rw<double> P_bar) {
  const double dt = clock.duration(clock.next - clock.now), half_dt = 0.5 * dt;
  const bool smoothed_pressure = P_bar.data() != nullptr;
  flecsi_lite::forall(
    x.size(),
    [&](std::size_t a) {
      const vector<D>& acc = acceleration(a);
      if (kind(a) != particle_kind::fluid) {
        accumulate_on_wall<D>(half_dt, acc, du_dt(a), impulse(a), work(a));
        v_half(a) = v(a);
        u_half(a) = u(a);
        time_bin(a) = wall_bin;
        step_begin(a) = clock.now;
        step_end(a) = clock.next;
        return;
      }
      const double length = clock.duration(step_end(a) - step_begin(a));
      if (step_begin(a) == clock.now) {
        for (int k = 0; k < D; ++k) v_half(a)[k] = v(a)[k] + 0.5 * length * acc[k];
        u_half(a) = u(a) + 0.5 * length * du_dt(a);
      }
      drift_by<D>(dt, v_half(a), space, x(a), drift(a));
      const double since_middle = clock.duration(clock.next - step_begin(a)) - 0.5 * length;
      for (int k = 0; k < D; ++k) v(a)[k] = v_half(a)[k] + since_middle * acc[k];
      const double u_before = u(a);
      u(a) = u_half(a) + since_middle * du_dt(a);
      if (step_end(a) == clock.next) return;  // active at next: its density is computed there
      // Inactive: rho and h follow the flow's compression (drho/dt = -rho div v, h ~ rho^(-1/D)),
      // so that active neighbours see them at the current time (GADGET-2, sec. 5; SWIFT's drift).
      const double stretch = std::clamp(dt * velocity_divergence(a), -0.5, 0.5);
      // exp(+-0) is exactly 1: the particles at rest (most of a blast's) skip the two calls.
      const double compression = stretch == 0 ? 1.0 : std::exp(-stretch);
      rho(a) *= compression;
      if (adaptive_h) h(a) *= stretch == 0 ? 1.0 : std::exp(stretch / D);
      // Pressure-energy: P_bar follows rho and the particle's own u (SWIFT's PressureEnergy
      // drift): the neighbours' new u would need another pass over them.
      if (smoothed_pressure) P_bar(a) *= compression * (u_before > 0 ? u(a) / u_before : 1.0);
    },
    "sph::kick_drift_bins");
}

/// The second kick of the active particles (their step ends at clock.next) with the new forces.
/// Returns how many fluid particles it kicked.
template<int D>
double kick_bins(timeline clock, ro<particle_kind> kind, ro<vector<D>> v_half, ro<double> u_half,
                 ro<vector<D>> acceleration, ro<double> du_dt, ro<std::int64_t> step_begin, ro<std::int64_t> step_end,
                 rw<vector<D>> v, rw<double> u, rw<vector<D>> impulse, rw<double> work) {
  const double half_dt = 0.5 * clock.duration(clock.next - clock.now);
  double kicked = 0;
  flecsi_lite::forall_reduce(
    v.size(),
    [&](std::size_t a, double& count) {
      if (step_end(a) != clock.next) return;
      const vector<D>& acc = acceleration(a);
      if (kind(a) != particle_kind::fluid) {
        accumulate_on_wall<D>(half_dt, acc, du_dt(a), impulse(a), work(a));
        v(a) = v_half(a);
        u(a) = u_half(a);
        return;
      }
      const double half = 0.5 * clock.duration(step_end(a) - step_begin(a));
      for (int k = 0; k < D; ++k) v(a)[k] = v_half(a)[k] + half * acc[k];
      u(a) = u_half(a) + half * du_dt(a);
      count += 1;
    },
    Kokkos::Sum<double>(kicked), "sph::kick_bins");
  return kicked;
}

/// The new bins of the particles whose step ended at clock.now (before the limiter): the largest
/// bin whose step their criterion (own_time_step) allows, at most `largest`, at most one above the
/// last (`first`: no last), and one whose steps can start now. Returns the smallest criterion of a
/// particle that even one tick cannot hold (NaN as -1; the largest double when there is none).
template<int D>
double assign_bins(timeline clock, int largest, bool first, ro<particle_kind> kind, ro<double> own_time_step,
                   ro<std::int64_t> step_end, rw<std::int32_t> time_bin) {
  double failed = std::numeric_limits<double>::max();
  flecsi_lite::forall_reduce(
    time_bin.size(),
    [&](std::size_t a, double& worst) {
      if (kind(a) != particle_kind::fluid || step_end(a) != clock.now) return;
      int bin = bin_of_step(own_time_step(a), clock.tick, largest);
      if (bin < 0) {
        worst = std::min(worst, std::isnan(own_time_step(a)) ? -1.0 : own_time_step(a));
        bin = 0;
      }
      if (!first) bin = std::min(bin, time_bin(a) + 1);
      time_bin(a) = aligned_bin(bin, clock.now);
    },
    Kokkos::Min<double>(failed), "sph::assign_bins");
  return failed;
}

namespace detail {
/// Calls visit(a) in parallel for every owned particle a whose step ends at tick `now` (visit
/// tests it again, and may be called for others): over the active targets select_active chose
/// for `now` when it has (every fluid particle whose step ends then is one: the system step
/// searched exactly those), else over every owned particle. The bins' passes then cost what the
/// active particles need, not a test of every particle's step end.
template<int D, class Visit>
void for_each_ending_at(const neighbourhood<D>& n, std::int64_t now, std::size_t owned, const Visit& visit,
                        const char* name) {
  if (n.active_tick != now) {
    flecsi_lite::forall(owned, visit, name);
    return;
  }
  const std::vector<std::uint32_t>&interior = n.active_interior, &boundary = n.active_boundary;
  flecsi_lite::forall(
    interior.size() + boundary.size(),
    [&](std::size_t i) { visit(i < interior.size() ? interior[i] : boundary[i - interior.size()]); }, name);
}

/// Whether entry j of a's list is within the kernel support of either, |r_ab| < 2 max(h_a, h_b):
/// the pairs of the force sums, which the limiter looks at.
template<int D, class Positions, class Lengths>
bool within_kernel(const neighbour_row<D>& row, const Positions& x, const Lengths& h, std::size_t a, std::size_t j) {
  const std::size_t b = row.neighbour(j);
  const double reach = physics::kernel_support * std::max(h(a), h(b));
  vector<D> r;
  return row.separation(x(a), x(b), j, r) < reach * reach;
}
}  // namespace detail

/// The smallest bin among the neighbours of each active particle (its step ended at `now`) within
/// the kernel support of either (|r_ab| < 2 max(h_a, h_b), the pairs of the force sums), itself
/// included, from its list (the search's lists hold the active particles' rows only).
template<int D>
void find_neighbour_bins(neighbours_ro<D> neighbours, std::int64_t now, ro_with_ghosts<vector<D>> x,
                         ro_with_ghosts<double> h, ro_with_ghosts<std::int32_t> time_bin, ro<std::int64_t> step_end,
                         rw<std::int32_t> neighbour_bin) {
  const neighbour_walk<D> walk(*neighbours);
  detail::for_each_ending_at(
    *neighbours, now, neighbours->size(),
    [&](std::size_t a) {
      if (step_end(a) != now) return;
      std::int32_t smallest = time_bin(a);
      // A neighbour's bin is read before its distance: one that cannot lower the minimum (most
      // of them, in a smooth flow) needs no separation.
      const neighbour_row<D> row = walk.row(a);
      for (std::size_t j = 0, end = row.size(); j < end; ++j)
        if (const std::int32_t bin = time_bin(row.neighbour(j));
            bin < smallest && detail::within_kernel(row, x, h, a, j))
          smallest = bin;
      neighbour_bin(a) = smallest;
    },
    "sph::find_neighbour_bins");
}

/// The limiter on the active particles (`levels` = log2 of time_step_limiter; negative: off):
/// at most the smallest neighbour bin + levels; then each starts its next step.
template<int D>
void limit_active_bins(neighbours_ro<D> neighbours, std::int64_t now, int levels, ro<particle_kind> kind,
                       ro<std::int32_t> neighbour_bin, rw<std::int32_t> time_bin, rw<std::int64_t> step_begin,
                       rw<std::int64_t> step_end) {
  detail::for_each_ending_at(
    *neighbours, now, time_bin.size(),
    [&](std::size_t a) {
      if (kind(a) != particle_kind::fluid || step_end(a) != now) return;
      if (levels >= 0) time_bin(a) = std::min(time_bin(a), neighbour_bin(a) + levels);  // aligned: smaller than one
      step_begin(a) = now;
      step_end(a) = now + timeline::ticks_of(time_bin(a));
    },
    "sph::limit_active_bins");
}

/// For each inactive particle, the smallest bin among the particles that started a step at `now`
/// within 2 max(h_a, h_b) of it, as SWIFT's limiter looks from the active particles at their
/// neighbours: from the sources' lists (searched this step with 2 (1 + search_margin) max(h),
/// enough for the h the density grew), which hold the owned and the ghost neighbours. A waiting
/// ghost's bound is its owner's contribution (ghost slots), combined into the owner's bound by
/// the ghost reduction that follows (reduce_ghosts, a minimum: the same in any order, so on any
/// rank count). Active ones keep their bound (find_neighbour_bins). A source whose bin + `levels`
/// does not lie below b's own bin cannot wake b (wake_bins: b wakes when its bin exceeds the
/// smallest source bin + levels, and then takes that value, which a source below it gives), so
/// it is left out: b's bound may stay higher, but wake_bins decides the same and sets the same
/// bins (the bound is read nowhere else).
template<int D>
void find_waking_bins(neighbours_ro<D> neighbours, std::int64_t now, int levels, ro_with_ghosts<vector<D>> x,
                      ro_with_ghosts<double> h, ro_with_ghosts<std::int64_t> step_begin,
                      ro_with_ghosts<std::int32_t> time_bin,
                      accessor<std::int32_t, flecsi_lite::rw, flecsi_lite::wo> neighbour_bin) {
  const std::size_t owned = neighbour_bin.owned_size();
  std::int32_t* bound = neighbour_bin.data();
  const auto waits = [&](std::size_t b) { return step_begin(b) != now; };
  // Whether a source of bin `bin` can wake the waiting particle b (above).
  const auto can_wake = [&](std::size_t b, std::int32_t bin) { return time_bin(b) - levels > bin; };
  // Every ghost slot starts at the largest bin (a contribution that lowers nothing).
  flecsi_lite::forall(
    neighbour_bin.size(),
    [&](std::size_t b) {
      if (b >= owned || waits(b)) bound[b] = wall_bin;
    },
    "sph::find_waking_bins::start");
  const neighbour_walk<D> walk(*neighbours);
  // The sources started their step now: the fluid particles whose step ended now
  // (limit_active_bins), among the targets of this step's search.
  detail::for_each_ending_at(
    *neighbours, now, owned,
    [&](std::size_t a) {
      if (step_begin(a) != now) return;
      const std::int32_t bin = time_bin(a);
      const neighbour_row<D> row = walk.row(a);
      for (std::size_t j = 0, end = row.size(); j < end; ++j) {
        const std::size_t b = row.neighbour(j);
        // Bounds only fall: one already at or below a's bin stays where it is, and the
        // separation is left out (a neighbour shared by several active particles). A relaxed
        // atomic read: another thread may lower the bound meanwhile, which only costs a test.
        // The bins first: most neighbours' cannot be woken by a, and their step start is not read.
        if (can_wake(b, bin) && waits(b) && bin < __atomic_load_n(&bound[b], __ATOMIC_RELAXED) &&
            detail::within_kernel(row, x, h, a, j))
          Kokkos::atomic_fetch_min(&bound[b], bin);
      }
    },
    "sph::find_waking_bins");
}

/// Wakes the inactive particles whose bin exceeds the bound of find_waking_bins + levels: the
/// step ends at the next multiple of the smaller step after now, and the first kick is shortened
/// to the new length (v_half, u_half move by half the difference times a, du), as if the step had
/// started with that length. Returns how many it woke.
template<int D>
double wake_bins(timeline clock, int levels, ro<particle_kind> kind, ro<std::int32_t> neighbour_bin,
                 ro<vector<D>> acceleration, ro<double> du_dt, ro<std::int64_t> step_begin, rw<std::int32_t> time_bin,
                 rw<std::int64_t> step_end, rw<vector<D>> v_half, rw<double> u_half) {
  double woken = 0;
  flecsi_lite::forall_reduce(
    time_bin.size(),
    [&](std::size_t a, double& count) {
      if (kind(a) != particle_kind::fluid || step_begin(a) == clock.now) return;
      const std::int32_t bound = std::min<std::int32_t>(wall_bin, neighbour_bin(a) + levels);
      if (time_bin(a) <= bound) return;
      const std::int64_t step = timeline::ticks_of(bound);
      const std::int64_t end = (clock.now / step + 1) * step;
      time_bin(a) = bound;
      if (end >= step_end(a)) return;
      const double shortening = 0.5 * clock.duration(end - step_end(a));  // < 0
      for (int k = 0; k < D; ++k) v_half(a)[k] += shortening * acceleration(a)[k];
      u_half(a) += shortening * du_dt(a);
      step_end(a) = end;
      count += 1;
    },
    Kokkos::Sum<double>(woken), "sph::wake_bins");
  return woken;
}

/// The earliest end of a fluid particle's step (timeline::span when there is none), as a double
/// (exact below 2^53).
template<int D>
double earliest_step_end(ro<particle_kind> kind, ro<std::int64_t> step_end) {
  // A minimum of integers without a branch (the loop vectorises: it reads every particle each
  // system step), converted once; a wall's end counts as the span.
  std::int64_t earliest = timeline::span;
  flecsi_lite::forall_reduce(
    step_end.size(),
    [&](std::size_t a, std::int64_t& e) {
      e = std::min(e, kind(a) == particle_kind::fluid ? step_end(a) : timeline::span);
    },
    Kokkos::Min<std::int64_t>(earliest), "sph::earliest_step_end");
  return static_cast<double>(std::min(earliest, timeline::span));  // the reduction's identity is huge
}

/// The largest bin max_time_step allows (timeline::bins without a bound).
inline int largest_bin(const physics_settings& physics, const timeline& clock) {
  if (!(physics.time_steps.max_time_step > 0)) return timeline::bins;
  const int bin = bin_of_step(physics.time_steps.max_time_step, clock.tick, timeline::bins);
  if (bin < 0) {
    std::ostringstream m;
    m << "sph: max_time_step = " << physics.time_steps.max_time_step << " is below the timeline's resolution "
      << clock.tick << " (the run's span / 2^" << timeline::bins << ")";
    throw flecsi_lite::runtime::parameter_error(m.str());
  }
  return bin;
}

/// log2 of time_step_limiter (-1: off).
inline int limiter_levels(const physics_settings& physics) {
  return physics.time_steps.limiter == 0 ? -1 : std::ilogb(static_cast<double>(physics.time_steps.limiter));
}

/// Starts the timeline at s.time, every particle active at its tick 0.
template<int D>
void start_timeline(simulation<D>& s) {
  using f = fields<D>;
  auto& p = *s.particles;
  s.clock = timeline::spanning(s.time, s.run.end_time);
  flecsi_lite::execute<start_time_bins<D>>(f::time_bin(p), f::step_begin(p), f::step_end(p));
}

/// The pair tasks of this system step for the particles whose step ends at s.clock.next.
template<int D>
void select_active_targets(simulation<D>& s) {
  using f = fields<D>;
  auto& p = *s.particles;
  s.active_targets = flecsi_lite::reduce<select_active<D>, active_count_sum>(
    s.neighbours, s.clock.next, f::step_end(p), f::time_bin(p),
    f::work(p).only_if(s.physics.balance == tree::balance::work));
}

/// Searches the neighbours of the particles whose step ends at s.clock.next (the others' rows
/// stay empty).
template<int D>
void find_active_neighbours(simulation<D>& s) {
  auto& p = *s.particles;
  flecsi_lite::execute<search_active_neighbours<D>>(p.local_tree_object(), s.neighbours, p.settings().support,
                                                    p.space(), s.physics.neighbour_lists, s.clock.next,
                                                    fields<D>::step_end(p));
}

template<int D>
void first_kick_and_drift_bins(simulation<D>& s) {
  using f = fields<D>;
  auto& p = *s.particles;
  flecsi_lite::execute<kick_drift_bins<D>>(
    s.clock, p.space(), s.physics.adaptive_smoothing_length, f::kind(p), f::position()(p), f::velocity(p),
    f::velocity_half(p), f::internal_energy(p), f::internal_energy_half(p), f::acceleration(p),
    f::internal_energy_rate(p), f::velocity_divergence(p), f::density(p), f::smoothing_length()(p),
    f::boundary_impulse(p).only_if(s.has_walls), f::boundary_work(p).only_if(s.has_walls), f::drift(p), f::time_bin(p),
    f::step_begin(p), f::step_end(p), f::smoothed_pressure(p).only_if(s.physics.pressure_energy()));
}

template<int D>
void second_kick_bins(simulation<D>& s) {
  using f = fields<D>;
  auto& p = *s.particles;
  s.kicked = flecsi_lite::reduce<kick_bins<D>, flecsi_lite::reduction::sum>(
    s.clock, f::kind(p), f::velocity_half(p), f::internal_energy_half(p), f::acceleration(p),
    f::internal_energy_rate(p), f::step_begin(p), f::step_end(p), f::velocity(p), f::internal_energy(p),
    f::boundary_impulse(p).only_if(s.has_walls), f::boundary_work(p).only_if(s.has_walls));
}

/// With individual time steps: moves the clock to the end of the step just taken (`advance`),
/// gives the particles that ended their step there their new bins (assign_bins, then the
/// limiter), and sets the next system step: s.clock.next, the earliest end, and s.dt.
template<int D>
void choose_time_bins(simulation<D>& s, bool advance) {
  using f = fields<D>;
  auto& p = *s.particles;
  if (advance) {
    s.particle_updates += s.kicked.get();
    s.clock.now = s.clock.next;
    s.time = s.clock.time_at(s.clock.now, s.run.end_time);
    ++s.step;
    const bool last = s.clock.now >= timeline::span;
    s.finished = last || (s.run.max_steps > 0 && s.step >= s.run.max_steps);
    if (last) return;  // dt stays the last step's, for the reports
  }
  const double failed = flecsi_lite::reduce<assign_bins<D>, flecsi_lite::reduction::min>(
                          s.clock, largest_bin(s.physics, s.clock), !advance, f::kind(p), f::own_time_step(p),
                          f::step_end(p), f::time_bin(p))
                          .get();
  if (failed < std::numeric_limits<double>::max()) {
    std::ostringstream m;
    m.precision(6);
    m << "sph: a particle's time step " << failed << " at t = " << s.time << " (step " << s.step
      << ") is below one tick of the individual time steps' timeline, " << s.clock.tick << " (the run's span / 2^"
      << timeline::bins << "): its state makes the step collapse (h without neighbours, or pressures, densities "
      << "or energies out of range), not courant = " << s.physics.courant
      << " or acceleration_factor = " << s.physics.acceleration_factor;
    throw std::runtime_error(m.str());
  }
  const int levels = limiter_levels(s.physics);
  if (levels >= 0)
    flecsi_lite::execute<find_neighbour_bins<D>>(s.neighbours, s.clock.now, f::position()(p), f::smoothing_length()(p),
                                                 f::time_bin(p), f::step_end(p), f::neighbour_bin(p));
  flecsi_lite::execute<limit_active_bins<D>>(s.neighbours, s.clock.now, levels, f::kind(p), f::neighbour_bin(p),
                                             f::time_bin(p), f::step_begin(p), f::step_end(p));
  if (levels >= 0) {
    flecsi_lite::execute<find_waking_bins<D>>(s.neighbours, s.clock.now, levels, f::position()(p),
                                              f::smoothing_length()(p), f::step_begin(p), f::time_bin(p),
                                              f::neighbour_bin(p));
    flecsi_lite::reduce_ghosts<flecsi_lite::reduction::min>(f::neighbour_bin(p));
    s.woken += flecsi_lite::reduce<wake_bins<D>, flecsi_lite::reduction::sum>(
                 s.clock, levels, f::kind(p), f::neighbour_bin(p), f::acceleration(p), f::internal_energy_rate(p),
                 f::step_begin(p), f::time_bin(p), f::step_end(p), f::velocity_half(p), f::internal_energy_half(p))
                 .get();
  }
  s.clock.next = static_cast<std::int64_t>(
    flecsi_lite::reduce<earliest_step_end<D>, flecsi_lite::reduction::min>(f::kind(p), f::step_end(p)).get());
  s.dt = s.clock.duration(s.clock.next - s.clock.now);
}

}  // namespace flecsph::sph
