// The SPH driver (seed Algorithm 3) as a control model: the physics steps of one time step as
// actions, ordered by their dependencies, in a cycle of advance, analyze and output that apps
// configure with their initial data, output and reports.
//
//   initial_data                      (the app: particles and their fields)
//   initialize    search -> density -> equation_of_state -> forces -> first_time_step -> diagnostics
//   evolve: while time < end_time
//     advance     kick_drift -> search -> density -> equation_of_state -> forces -> kick -> clock
//     analyze     conserved_quantities, progress
//     output      (the app)
//   finalize      summary (then the app's reports)
#pragma once

#include "specialization/sph/conserved.hh"
#include "specialization/sph/density.hh"
#include "specialization/sph/equation_of_state.hh"
#include "specialization/sph/forces.hh"
#include "specialization/sph/initial_fields.hh"
#include "specialization/sph/integrator.hh"
#include "specialization/sph/redistribution.hh"
#include "specialization/sph/simulation.hh"

#include "flecsi_lite/control.hh"
#include "flecsi_lite/execution.hh"
#include "flecsi_lite/runtime.hh"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <limits>
#include <sstream>
#include <stdexcept>
#include <string>
#include <utility>

namespace flecsph::sph {

/// Total length of this rank's neighbour lists (for the mean neighbour count).
template<int D>
double neighbour_total(const neighbourhood<D>& neighbours) {
  return static_cast<double>(neighbours.lists.total());
}

/// Distributes the particles (sample sort, ghosts, local tree) when `redistribute` is set or when
/// the particles' motion and growth of h since the last distribution could have brought particles
/// that are not ghosts here within reach; otherwise refits the local tree to the current
/// positions and h (ghost values are copied first). Then finds every owned particle's neighbours.
/// The decision depends only on particle values, so it is the same on any number of ranks.
/// Collective.
template<int D>
void update_neighbours(simulation<D>& s, bool redistribute = false) {
  using f = fields<D>;
  auto& p = *s.particles;
  if (!redistribute) {
    const auto slack = flecsi_lite::reduce<measure_distribution_slack, slack_reduction>(
                         f::smoothing_length()(p), f::drift(p), f::distributed_h(p))
                         .get();
    redistribute = !ghosts_still_suffice(slack, p.settings().support, s.physics.distribution_skin);
  }
  if (redistribute) {
    p.distribute();
    flecsi_lite::execute<mark_distributed>(f::smoothing_length()(p), f::drift(p), f::distributed_h(p));
    ++s.distributions;
  } else {
    p.refresh_local_tree();
  }
  flecsi_lite::wait_all();  // no pending launch may still read the lists replaced here
  flecsi_lite::timers::scoped timer("sph::neighbour search");
  find_neighbours(p, s.neighbours);
}

/// Density and smoothing length; when some h outgrew the searched reach, searches again with the
/// grown h and repeats (the same decision on every rank, so results stay rank-count independent).
/// The search again redistributes only when the ghosts no longer suffice for the grown h.
template<int D>
void update_density(simulation<D>& s) {
  using f = fields<D>;
  auto& p = *s.particles;
  for (int attempt = 0;; ++attempt) {
    const double worst =
      flecsi_lite::reduce<compute_density<D>, flecsi_lite::reduction::max>(
        s.neighbours, s.physics, f::position()(p), f::mass()(p), f::kind(p), f::smoothing_length()(p),
        f::density(p), f::omega(p))
        .get();
    if (worst <= 1.0) return;
    if (attempt == 20)
      throw std::runtime_error("sph: the smoothing length keeps outgrowing the neighbour search (" +
                               std::to_string(worst) + " times the reach); raise search_margin");
    ++s.repeated_searches;
    update_neighbours(s);
  }
}

/// Velocity gradients (for the Balsara switch), pressure and sound speed.
template<int D>
void update_pressure(simulation<D>& s) {
  using f = fields<D>;
  auto& p = *s.particles;
  if (s.physics.balsara)
    flecsi_lite::execute<compute_velocity_gradients<D>>(
      s.neighbours, s.physics, f::position()(p), f::velocity(p), f::mass()(p), f::smoothing_length()(p),
      f::density(p), f::omega(p), f::velocity_divergence(p), f::velocity_curl(p));
  flecsi_lite::execute<compute_equation_of_state<D>>(s.physics, f::density(p), f::internal_energy(p),
                                                     f::smoothing_length()(p), f::omega(p),
                                                     f::velocity_divergence(p), f::velocity_curl(p), f::pressure(p),
                                                     f::sound_speed(p), f::pressure_term(p), f::balsara(p));
}

/// Accelerations and du/dt; the next time step (global minimum) becomes s.next_time_step.
template<int D>
void update_forces(simulation<D>& s) {
  using f = fields<D>;
  auto& p = *s.particles;
  s.next_time_step = flecsi_lite::reduce<compute_forces<D>, flecsi_lite::reduction::min>(
    s.neighbours, s.physics, f::position()(p), f::velocity(p), f::mass()(p), f::smoothing_length()(p),
    f::density(p), f::pressure(p), f::sound_speed(p), f::pressure_term(p), f::internal_energy(p), f::balsara(p),
    f::kind(p), f::acceleration(p), f::internal_energy_rate(p));
}

template<int D>
void first_kick_and_drift(simulation<D>& s) {
  using f = fields<D>;
  auto& p = *s.particles;
  flecsi_lite::execute<kick_drift<D>>(s.dt, p.space(), f::kind(p), f::position()(p), f::velocity(p),
                                      f::velocity_half(p), f::internal_energy(p), f::internal_energy_half(p),
                                      f::acceleration(p), f::internal_energy_rate(p), f::boundary_impulse(p),
                                      f::boundary_work(p), f::drift(p));
}

template<int D>
void second_kick(simulation<D>& s) {
  using f = fields<D>;
  auto& p = *s.particles;
  flecsi_lite::execute<kick<D>>(s.dt, f::kind(p), f::velocity_half(p), f::internal_energy_half(p),
                                f::acceleration(p), f::internal_energy_rate(p), f::velocity(p),
                                f::internal_energy(p), f::boundary_impulse(p), f::boundary_work(p));
}

/// The step just taken moves the clock; the next step is the global minimum of the particles'
/// time steps, shortened to end exactly at end_time. The minimum over ranks is exact, so every
/// rank count takes the same steps.
template<int D>
void choose_time_step(simulation<D>& s, bool advance) {
  if (advance) {
    const bool last = s.dt >= s.run.end_time - s.time;
    s.time = last ? s.run.end_time : s.time + s.dt;
    ++s.step;
    s.finished = last || (s.run.max_steps > 0 && s.step >= s.run.max_steps);
    if (s.finished) return;  // dt stays the last step's, for the reports and the output
  }
  double next = s.next_time_step.get();
  if (next >= std::numeric_limits<double>::max()) next = s.run.end_time - s.time;  // no fluid particle
  if (!(next > 0))
    throw std::runtime_error("sph: time step " + std::to_string(next) + " at t = " + std::to_string(s.time) +
                             " (step " + std::to_string(s.step) + ")");
  s.dt = std::min(next, s.run.end_time - s.time);
}

/// The exact totals now (collective; waits for the launches they depend on).
template<int D>
conserved_totals<D> measure_conserved(simulation<D>& s) {
  using f = fields<D>;
  auto& p = *s.particles;
  return flecsi_lite::reduce<conserved_quantities<D>, conserved_reduction>(
           f::position()(p), f::velocity(p), f::mass()(p), f::internal_energy(p), f::kind(p),
           f::boundary_impulse(p), f::boundary_work(p))
    .get()
    .totals();
}

template<int D>
std::string describe_conserved(const conserved_totals<D>& t, const conserved_totals<D>& initial) {
  std::ostringstream out;
  out << std::setprecision(12) << "mass " << t.mass << "  momentum (";
  for (int k = 0; k < D; ++k) out << (k ? ", " : "") << t.momentum[k];
  out << ")";
  if constexpr (angular_components<D> > 0) {
    out << "  angular momentum (";
    for (int k = 0; k < angular_components<D>; ++k) out << (k ? ", " : "") << t.angular_momentum[k];
    out << ")";
  }
  out << "  kinetic " << t.kinetic << "  internal " << t.internal << "  total " << t.total;
  if (t.boundary != 0) out << " (walls " << t.boundary << ")";
  out << std::setprecision(3) << "  relative energy change "
      << (initial.total != 0 ? (t.total - initial.total) / std::fabs(initial.total) : t.total - initial.total);
  return out.str();
}

template<int D>
void conserved_diagnostics(simulation<D>& s) {
  const long every = s.run.diagnostics_every;
  const bool first = s.totals_step < 0;
  if (!(first || s.finished || (every > 0 && s.step % every == 0))) return;
  s.totals = measure_conserved(s);
  s.totals_step = s.step;
  if (first && !s.restarted) s.initial_totals = s.totals;  // a restart keeps the run's initial totals
  flecsi_lite::log::info() << "conserved: step " << s.step << "  t " << std::setprecision(8) << s.time << "  "
                           << describe_conserved(s.totals, s.initial_totals);
}

/// Throughput of this run since the cycle started (a restart counts from its own first step).
template<int D>
double particle_steps_per_second(const simulation<D>& s) {
  const double steps = static_cast<double>(s.step - s.started_step);
  return s.elapsed > 0 ? static_cast<double>(s.particles->global_size()) * steps / s.elapsed : 0.0;
}

template<int D>
void progress_line(simulation<D>& s) {
  s.elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - s.started).count();
  const long every = s.run.progress_every;
  if (!(s.finished || (every > 0 && s.step % every == 0))) return;
  const double total = flecsi_lite::reduce<neighbour_total<D>, flecsi_lite::reduction::sum>(s.neighbours).get();
  s.mean_neighbours = s.particles->global_size() ? total / double(s.particles->global_size()) : 0.0;
  const double fraction = s.run.end_time > 0 ? s.time / s.run.end_time : 1.0;
  const double rate = particle_steps_per_second(s);
  std::ostringstream line;
  line << "step " << std::setw(6) << s.step << "  t " << std::setw(10) << std::setprecision(6) << s.time << "  dt "
       << std::setw(10) << s.dt << "  " << std::fixed << std::setprecision(1) << std::setw(5) << 100 * fraction
       << "%  ETA " << std::setprecision(1)
       << (s.time > s.started_time ? s.elapsed * (s.run.end_time - s.time) / (s.time - s.started_time) : 0.0)
       << " s  " << std::scientific << std::setprecision(3) << rate << " particle-steps/s  "
       << std::fixed << std::setprecision(1) << s.mean_neighbours << " neighbours";
  flecsi_lite::log::info() << line.str();
}

/// Memory of this rank per owned particle: every field's storage (owned and ghost entries), and
/// the neighbour lists.
struct memory_use {
  double fields = 0;
  double neighbour_lists = 0;
};

template<int D>
memory_use measure_memory(const simulation<D>& s) {
  memory_use result;
  const double owned = static_cast<double>(std::max<std::size_t>(1, s.particles->owned_size()));
  for (const auto& storage : s.particles->storages())
    if (storage) result.fields += static_cast<double>(storage->element_size() * storage->size());
  const auto& lists = s.neighbours.lists;  // what is allocated, spare room included
  result.neighbour_lists = static_cast<double>(lists.offsets.capacity() * sizeof(std::size_t) +
                                               lists.neighbours.capacity() * sizeof(std::uint32_t) +
                                               lists.shifts.capacity() * sizeof(tree::shift_code));
  result.fields /= owned;
  result.neighbour_lists /= owned;
  return result;
}

/// The standard SPH control model for a state type deriving from simulation<D>. The app
/// registers its actions on "initial_data" (create_particles and fill the fields), "output"
/// and "finalize" (and may add more anywhere), then calls execute(state).
template<class State>
flecsi_lite::control::control_model<State> make_control_model() {
  constexpr int D = State::dimension;
  using base = simulation<D>;
  flecsi_lite::control::control_model<State> m;
  m.point("initial_data")
    .point("initialize")
    .cycle("evolve", {"advance", "analyze", "output"},
           [](const State& s) { return !s.finished && s.time < s.run.end_time; })
    .point("finalize");

  const auto on = [&m](const std::string& point, const std::string& name, void (*action)(base&)) {
    return m.action(point, name, [action](State& s) { action(s); });
  };
  // initialize: the state at t = 0 and the first time step (a restart restored them all).
  {
    auto search = on("initialize", "search", [](base& s) {
      if (!s.particles) throw std::logic_error("sph: the initial_data point must create the particles");
      update_neighbours(s, true);
    });
    auto density = on("initialize", "density", [](base& s) {
      if (!s.restarted) update_density(s);
    });
    auto pressure = on("initialize", "equation_of_state", [](base& s) {
      if (!s.restarted) update_pressure(s);
    });
    auto forces = on("initialize", "forces", [](base& s) {
      if (!s.restarted) update_forces(s);
    });
    auto step = on("initialize", "first_time_step", [](base& s) {
      if (!s.restarted) choose_time_step(s, false);
    });
    auto diagnostics = on("initialize", "diagnostics", [](base& s) {
      conserved_diagnostics(s);
      s.started = std::chrono::steady_clock::now();
      s.started_step = s.step;
      s.started_time = s.time;
    });
    m.depends(density, search).depends(pressure, density).depends(forces, pressure).depends(step, forces);
    m.depends(diagnostics, step);
  }
  // advance: one kick-drift-kick step.
  {
    auto drift = on("advance", "kick_drift", first_kick_and_drift<D>);
    auto search = on("advance", "search", [](base& s) {
      update_neighbours(s, std::exchange(s.redistribute_next, false));
    });
    auto density = on("advance", "density", update_density<D>);
    auto pressure = on("advance", "equation_of_state", update_pressure<D>);
    auto forces = on("advance", "forces", update_forces<D>);
    auto kick = on("advance", "kick", second_kick<D>);
    auto clock = on("advance", "clock", [](base& s) { choose_time_step(s, true); });
    m.depends(search, drift).depends(density, search).depends(pressure, density).depends(forces, pressure);
    m.depends(kick, forces).depends(clock, kick);
  }
  on("analyze", "conserved_quantities", conserved_diagnostics<D>);
  auto progress = on("analyze", "progress", progress_line<D>);
  (void)progress;
  on("finalize", "summary", [](base& s) {
    const memory_use bytes = measure_memory(s);
    flecsi_lite::log::info() << "sph: " << s.step << " steps to t = " << s.time << " in " << std::setprecision(4)
                             << s.elapsed << " s: "
                             << particle_steps_per_second(s)
                             << " particle-steps/s, " << s.distributions << " distributions, "
                             << s.repeated_searches << " repeated searches; bytes per owned particle (rank 0): "
                             << std::setprecision(3) << bytes.fields << " in fields, " << bytes.neighbour_lists
                             << " in neighbour lists";
  });
  return m;
}

} // namespace flecsph::sph
