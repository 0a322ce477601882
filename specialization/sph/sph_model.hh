// The SPH driver (seed Algorithm 3) as a control model: the physics steps of one time step
// (steps.hh) as named actions, ordered by their dependencies, in a cycle of advance, analyze and
// output, with the diagnostics (diagnostics.hh). Apps add their initial data, output and reports,
// and may place their own tasks inside the step by name:
//
//   initial_data                      (the app: particles and their fields)
//   initialize    search -> density -> equation_of_state -> viscosity_switch -> forces -> first_time_step
//                 -> diagnostics
//   evolve: while time < end_time
//     advance     kick_drift -> search -> density -> equation_of_state -> viscosity_switch -> forces -> kick
//                 -> clock
//     analyze     conserved_quantities, progress
//     output      (the app)
//   finalize      summary (then the app's reports)
//
//   m.action("advance", "cooling", cool).after("forces");   // runs after forces, before kick
#pragma once

#include "specialization/sph/diagnostics.hh"
#include "specialization/sph/instances.hh"
#include "specialization/sph/simulation.hh"
#include "specialization/sph/steps.hh"
#include "specialization/sph/viscosity_switch.hh"

#include "flecsi_lite/control.hh"

#include <chrono>
#include <stdexcept>
#include <string>
#include <utility>

namespace flecsph::sph {

/// The standard SPH control model for a state type deriving from simulation<D>, its actions named
/// as in the table above. The app registers its actions on "initial_data" (create_particles and
/// fill the fields), "output" and "finalize", may place more inside any point by name
/// (`.after("forces")`, `.before("kick")`), then calls execute(state).
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
      // A restart distributed and searched as the run it continues had (read_restart_checkpoint).
      if (s.restarted) return;
      if (s.physics.individual_time_steps()) start_timeline(s);  // every particle active at t = 0
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
    // The Cullen & Dehnen alpha (a no-op unless viscosity_switch = on).
    auto alpha = on("initialize", "viscosity_switch", [](base& s) { update_viscosity_switch(s, true); });
    m.depends(density, search).depends(pressure, density).depends(forces, pressure).depends(step, forces);
    m.depends(alpha, pressure).depends(forces, alpha);
    m.depends(diagnostics, step);
  }
  // advance: one kick-drift-kick step.
  {
    auto drift = on("advance", "kick_drift", first_kick_and_drift<D>);
    auto search =
      on("advance", "search", [](base& s) { update_neighbours(s, std::exchange(s.redistribute_next, false)); });
    auto density = on("advance", "density", update_density<D>);
    auto pressure = on("advance", "equation_of_state", update_pressure<D>);
    auto forces = on("advance", "forces", update_forces<D>);
    auto kick = on("advance", "kick", second_kick<D>);
    auto clock = on("advance", "clock", [](base& s) { choose_time_step(s, true); });
    auto alpha = on("advance", "viscosity_switch", [](base& s) { update_viscosity_switch(s, false); });
    m.depends(search, drift).depends(density, search).depends(pressure, density).depends(forces, pressure);
    m.depends(alpha, pressure).depends(forces, alpha);
    m.depends(kick, forces).depends(clock, kick);
  }
  on("analyze", "conserved_quantities", conserved_diagnostics<D>);
  on("analyze", "progress", progress_line<D>);
  on("finalize", "summary", run_summary<D>);
  return m;
}

// Compiled in the library (instances_*.cc).
FLECSPH_SPH_STEP_INSTANCES(extern, 1)
FLECSPH_SPH_STEP_INSTANCES(extern, 2)
FLECSPH_SPH_STEP_INSTANCES(extern, 3)

}  // namespace flecsph::sph
