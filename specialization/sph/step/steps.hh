// The physics steps of one SPH time step (seed Algorithm 3), each a launch of the tasks of
// density.hh, equation_of_state.hh, forces.hh and integrator.hh on a simulation's particles:
// neighbour search (with redistribution when needed), density and h, pressure, forces, the two
// kicks of the leapfrog, and the choice of the next time step.
#pragma once

#include "specialization/sph/model/simulation.hh"
#include "specialization/sph/step/density.hh"
#include "specialization/sph/step/equation_of_state.hh"
#include "specialization/sph/step/forces.hh"
#include "specialization/sph/step/integrator.hh"
#include "specialization/sph/step/interior_then_boundary.hh"
#include "specialization/sph/step/list_reuse.hh"
#include "specialization/sph/step/redistribution.hh"
#include "specialization/sph/step/time_bins.hh"

#include "flecsi_lite/execution.hh"
#include "flecsi_lite/runtime.hh"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <tuple>

namespace flecsph::sph {

namespace detail {
/// The particle that limits the time step, for the message when it fails: the smallest of the
/// two criteria (a non-finite one first), with the values behind them.
struct time_step_report {
  double score = std::numeric_limits<double>::infinity();
  std::uint64_t id = 0;
  double h = 0, sound_speed = 0, acceleration = 0, courant_dt = 0, acceleration_dt = 0, rho = 0, p = 0, u = 0;
};
struct time_step_report_reduction {
  static time_step_report combine(const time_step_report& a, const time_step_report& b) {
    return (b.score < a.score || (b.score == a.score && b.id < a.id)) ? b : a;
  }
};
template<int D>
time_step_report limiting_particle(physics_settings settings, ro<std::uint64_t> id, ro<particle_kind> kind,
                                   ro<double> h, ro<double> c, ro<vector<D>> acceleration, ro<double> rho, ro<double> p,
                                   ro<double> u) {
  time_step_report worst;
  for (std::size_t a = 0; a < h.size(); ++a) {
    if (kind(a) != particle_kind::fluid) continue;
    time_step_report r;
    r.id = id(a), r.h = h(a), r.sound_speed = c(a), r.rho = rho(a), r.p = p(a), r.u = u(a);
    double a2 = 0;
    for (int k = 0; k < D; ++k) a2 += acceleration(a)[k] * acceleration(a)[k];
    r.acceleration = std::sqrt(a2);
    r.courant_dt = settings.courant * r.h / (2 * r.sound_speed);  // v_signal >= c_a + c_b
    r.acceleration_dt = settings.acceleration_factor * std::sqrt(r.h / r.acceleration);
    const double smallest = std::min(r.courant_dt, r.acceleration_dt);
    r.score = std::isfinite(r.courant_dt) && std::isfinite(r.acceleration_dt)
                ? smallest
                : -std::numeric_limits<double>::infinity();
    worst = time_step_report_reduction::combine(worst, r);
  }
  return worst;
}

/// "sph: the time step is 0 at t = ... (step ...): particle id ... limits it: ..." naming the
/// criteria, their keys and the particle's state.
template<int D>
std::string time_step_failure(simulation<D>& s, double next) {
  using f = fields<D>;
  auto& p = *s.particles;
  const auto r = flecsi_lite::reduce<limiting_particle<D>, time_step_report_reduction>(
                   s.physics, f::id()(p), f::kind(p), f::smoothing_length()(p), f::sound_speed(p), f::acceleration(p),
                   f::density(p), f::pressure(p), f::internal_energy(p))
                   .get();
  std::ostringstream m;
  m.precision(6);
  m << "sph: the time step is " << next << " at t = " << s.time << " (step " << s.step << "), smallest for particle id "
    << r.id << ": Courant criterion courant h / v_signal with courant = " << s.physics.courant << ", h = " << r.h
    << ", sound speed " << r.sound_speed << " gives about " << r.courant_dt
    << "; acceleration criterion acceleration_factor sqrt(h / |a|) with acceleration_factor = "
    << s.physics.acceleration_factor << ", |a| = " << r.acceleration << " gives " << r.acceleration_dt
    << ". Its state: rho = " << r.rho << ", P = " << r.p << ", u = " << r.u
    << ". A step that small (it must be > 0 and move t) comes from that state, not from courant or "
       "acceleration_factor: h collapsing (the particle has no neighbours: eta = "
    << s.physics.eta << " too small for its spacing) or pressures, densities or energies out of range";
  return m.str();
}
}  // namespace detail

/// Distributes the particles (sample sort, ghosts, local tree) when `redistribute` is set or when
/// the particles' motion and growth of h since the last distribution could have brought particles
/// that are not ghosts here within reach; otherwise, when their displacement and growth of h since
/// the last search could have brought a pair within reach that the lists lack (list_reuse.hh),
/// refits the local tree to the current positions and h (ghost values are copied first). After
/// either, searches every owned particle's neighbours; otherwise keeps the lists. A kept list
/// holds every pair a search now would, in the same (key, id, shift) order, and the pair tasks
/// skip the entries beyond the kernel support, so every sum takes the pairs of a search now in
/// its order. The decisions depend only on particle values (exact maxima over ranks), so they are
/// the same on any number of ranks. Collective.
template<int D>
void update_neighbours(simulation<D>& s, bool redistribute = false) {
  using f = fields<D>;
  auto& p = *s.particles;
  bool search = true;
  if (!redistribute) {
    const auto slack =
      flecsi_lite::reduce<measure_neighbour_slack<D>, neighbour_slack_reduction>(
        s.neighbours, p.space(), f::position()(p), f::smoothing_length()(p), f::drift(p), f::distributed_h(p))
        .get();
    const double support = p.settings().support;
    redistribute = !ghosts_still_suffice(slack.distribution, support, s.physics.distribution_skin);
    // Individual time steps search the active particles of every step (their rows only).
    search = redistribute || s.physics.individual_time_steps() ||
             !lists_still_suffice(slack.lists, support, s.physics.list_skin);
  }
  double count_imbalance = 0;
  if (redistribute) {
    // The last lists' costs (none yet: counts); individual time steps keep each particle's work
    // from its last active step (select_active).
    if (s.physics.balance == tree::balance::work && !s.physics.individual_time_steps())
      flecsi_lite::execute<measure_work<D>>(s.neighbours, f::work(p));
    const tree::distribution_stats distributed = p.distribute();
    count_imbalance = distributed.count_imbalance;
    s.moved_particles += distributed.moved;
    s.moved_bytes += double(distributed.moved) * double(distributed.bytes_per_particle);
    flecsi_lite::execute<mark_distributed<D>>(f::smoothing_length()(p), f::position()(p), f::drift(p),
                                              f::distributed_h(p), f::distributed_position(p));
    ++s.distributions;
  } else if (search) {
    p.refresh_local_tree();
  }
  if (search) {
    // A task: after the refit, and after the last readers of the old lists.
    if (s.physics.individual_time_steps())
      find_active_neighbours(s);
    else
      find_neighbours(p, s.neighbours, s.physics.list_skin, s.physics.neighbour_lists);
    ++s.searches;
    if (redistribute)
      s.balance.expect(count_imbalance,
                       flecsi_lite::reduce<neighbour_total<D>, flecsi_lite::reduction::max>(s.neighbours),
                       flecsi_lite::reduce<neighbour_total<D>, flecsi_lite::reduction::sum>(s.neighbours));
  }
  if (s.physics.individual_time_steps()) select_active_targets(s);
}

/// Density and smoothing length, and the velocity gradients where they are read (div v for the
/// Balsara switch or individual time steps' drift of the inactive particles' rho and h, |curl v|
/// for the Balsara switch); when some h outgrew the searched reach, searches again with the
/// grown h and repeats (the same decision on every rank, so results stay rank-count independent).
/// The search again redistributes only when the ghosts no longer suffice for the grown h.
/// Each pair task is launched over the interior targets, then the boundary ones
/// (interior_then_boundary.hh): the results are those of one launch, bit for bit.
template<int D>
void update_density(simulation<D>& s) {
  using f = fields<D>;
  using flecsi_lite::na, flecsi_lite::ro, flecsi_lite::reduction::max;
  auto& p = *s.particles;
  const auto launch = [&](auto... field) {
    if (s.physics.pressure_energy())
      return reduce_interior_then_boundary<compute_density_pressure_energy<D, na>,
                                           compute_density_pressure_energy<D, ro>, max>(
        s.neighbours, s.physics, 0.0, field..., f::internal_energy(p), f::smoothed_pressure(p), f::pressure_grad_h(p));
    if (s.physics.gravity.enabled)
      return reduce_interior_then_boundary<compute_density_with_gravity<D, na>, compute_density_with_gravity<D, ro>,
                                           max>(s.neighbours, s.physics, 0.0, field..., f::zeta_over_omega(p));
    return reduce_interior_then_boundary<compute_density<D, na>, compute_density<D, ro>, max>(s.neighbours, s.physics,
                                                                                              0.0, field...);
  };
  // The fields of a physics that is off are absent (only_if): no memory, the tasks' null paths.
  const bool gradients = s.physics.velocity_gradients();
  for (int attempt = 0;; ++attempt) {
    const double worst =
      std::apply(launch, std::make_tuple(f::position()(p), f::mass()(p), f::kind(p), f::smoothing_length()(p),
                                         f::density(p), f::omega(p), f::velocity(p).only_if(gradients),
                                         f::velocity_divergence(p).only_if(gradients),
                                         f::velocity_curl(p).only_if(s.physics.balsara)))
        .get();
    if (worst <= 1.0) return;
    if (attempt == 20) {
      std::ostringstream m;
      m.precision(6);
      m << "sph: the smoothing length still outgrows the neighbour search after 20 searches at step " << s.step
        << " (t = " << s.time << "): h reaches " << worst << " times the searched 2 (1 + search_margin) h, "
        << "search_margin = " << s.physics.search_margin << " (reach " << s.neighbours.host().reach
        << " h). Raise search_margin; if h grows without bound, a particle has no neighbours within 2 h (an "
           "isolated particle, or eta = "
        << s.physics.eta << " too small for the particle spacing)";
      throw std::runtime_error(m.str());
    }
    ++s.repeated_searches;
    update_neighbours(s);
  }
}

/// Pressure and sound speed (and the Balsara factor from the density pass's velocity gradients).
template<int D>
void update_pressure(simulation<D>& s) {
  using f = fields<D>;
  auto& p = *s.particles;
  flecsi_lite::execute<compute_equation_of_state<D>>(
    s.physics, f::density(p), f::internal_energy(p), f::smoothing_length()(p), f::omega(p),
    f::velocity_divergence(p).only_if(s.physics.velocity_gradients()), f::velocity_curl(p).only_if(s.physics.balsara),
    f::smoothed_pressure(p).only_if(s.physics.pressure_energy()), f::pressure(p), f::sound_speed(p),
    f::pressure_term(p), f::balsara(p).only_if(s.physics.balsara));
}

/// Accelerations and du/dt (with self-gravity: plus the grad-h gravity term and the tree's
/// acceleration of update_gravity, gravity.hh); the next time step (global minimum) becomes
/// s.next_time_step.
template<int D>
void update_forces(simulation<D>& s) {
  using f = fields<D>;
  auto& p = *s.particles;
  // P and u are read only by the conductivity and (u) pressure-energy SPH: otherwise their
  // ghosts are not copied for the forces.
  const bool conductivity = s.physics.conductivity > 0;
  const auto fields_read = std::make_tuple(
    f::position()(p), f::velocity(p), f::mass()(p), f::smoothing_length()(p), f::density(p),
    f::pressure(p).only_if(conductivity), f::sound_speed(p), f::pressure_term(p),
    f::internal_energy(p).only_if(conductivity || s.physics.pressure_energy()),
    f::balsara(p).only_if(s.physics.balsara), f::viscosity_alpha(p).only_if(s.physics.viscosity_switch.enabled));
  const auto fields_written =
    std::make_tuple(f::kind(p), f::acceleration(p), f::internal_energy_rate(p), f::own_time_step(p));
  const double none = std::numeric_limits<double>::max();
  using flecsi_lite::na, flecsi_lite::ro, flecsi_lite::reduction::min;
  if (s.physics.gravity.enabled) {
    s.next_time_step = std::apply(
      [&](auto... field) {
        return reduce_interior_then_boundary<compute_forces_with_gravity<D, na>, compute_forces_with_gravity<D, ro>,
                                             min>(s.neighbours, s.physics, none, field...);
      },
      std::tuple_cat(fields_read, std::make_tuple(f::zeta_over_omega(p), f::gravity_acceleration(p)), fields_written));
    return;
  }
  s.next_time_step = std::apply(
    [&](auto... field) {
      return reduce_interior_then_boundary<compute_forces<D, na>, compute_forces<D, ro>, min>(s.neighbours, s.physics,
                                                                                              none, field...);
    },
    std::tuple_cat(fields_read, std::make_tuple(f::pressure_grad_h(p).only_if(s.physics.pressure_energy())),
                   fields_written));
}

template<int D>
void first_kick_and_drift(simulation<D>& s) {
  using f = fields<D>;
  auto& p = *s.particles;
  if (s.physics.individual_time_steps()) return first_kick_and_drift_bins(s);
  flecsi_lite::execute<kick_drift<D>>(
    s.dt, p.space(), f::kind(p), f::position()(p), f::velocity(p), f::velocity_half(p), f::internal_energy(p),
    f::internal_energy_half(p), f::acceleration(p), f::internal_energy_rate(p),
    f::boundary_impulse(p).only_if(s.has_walls), f::boundary_work(p).only_if(s.has_walls), f::drift(p));
}

template<int D>
void second_kick(simulation<D>& s) {
  using f = fields<D>;
  auto& p = *s.particles;
  if (s.physics.individual_time_steps()) return second_kick_bins(s);
  flecsi_lite::execute<kick<D>>(s.dt, f::kind(p), f::velocity_half(p), f::internal_energy_half(p), f::acceleration(p),
                                f::internal_energy_rate(p), f::velocity(p), f::internal_energy(p),
                                f::boundary_impulse(p).only_if(s.has_walls), f::boundary_work(p).only_if(s.has_walls));
}

/// The step just taken moves the clock; the next step is the global minimum of the particles'
/// time steps, shortened to end exactly at end_time (individual time steps: choose_time_bins).
/// The minimum over ranks is exact, so every rank count takes the same steps.
template<int D>
void choose_time_step(simulation<D>& s, bool advance) {
  if (s.physics.individual_time_steps()) return choose_time_bins(s, advance);
  if (advance) {
    const bool last = s.dt >= s.run.end_time - s.time;
    s.time = last ? s.run.end_time : s.time + s.dt;
    ++s.step;
    s.finished = last || (s.run.max_steps > 0 && s.step >= s.run.max_steps);
    // dt stays the last step's, for the reports and the output; a run stopped by max_steps
    // before end_time takes the next step's, which its checkpoint needs.
    if (last) return;
  }
  double next = s.next_time_step.get();
  if (next >= std::numeric_limits<double>::max()) next = s.run.end_time - s.time;  // no fluid particle
  // A step that does not move t (zero, non-finite, or below the resolution of t) would never end.
  if (!(next > 0) || !(s.time + std::min(next, s.run.end_time - s.time) > s.time))
    throw std::runtime_error(detail::time_step_failure(s, next));
  s.dt = std::min(next, s.run.end_time - s.time);
}

}  // namespace flecsph::sph
