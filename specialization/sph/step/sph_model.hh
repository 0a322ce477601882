// The SPH driver (seed Algorithm 3) as a control model: the physics steps of one time step
// (steps.hh) as named actions, ordered by their dependencies, in a cycle of advance, analyze and
// output, with the diagnostics (diagnostics.hh). The force evaluation (search -> density ->
// equation_of_state -> viscosity_switch -> forces) is declared once, as the stage "force_evaluation" that
// "initialize" runs for the state at t = 0 (unless a restart restored it) and every "advance"
// runs after the drift. Apps add their initial data, output and reports, and place their own
// tasks by name:
//
//   initial_data                      (the app: particles and their fields)
//   initialize    start -> force_evaluation -> first_time_step -> diagnostics
//   evolve: while time < end_time
//     advance     kick_drift -> force_evaluation -> kick -> clock
//     analyze     conserved_quantities, progress
//     output      (the app)
//   finalize      summary (then the app's reports)
//   stage force_evaluation: search -> density -> equation_of_state -> viscosity_switch -> forces
//
//   m.action("force_evaluation", "cooling", cool).after("forces");  // at t = 0 and in every step
//   m.action("advance", "potential", push).before("kick");           // in every step only
#pragma once

#include "specialization/sph/instances.hh"
#include "specialization/sph/model/simulation.hh"
#include "specialization/sph/step/diagnostics.hh"
#include "specialization/sph/step/steps.hh"
#include "specialization/sph/step/viscosity_switch.hh"

#include "flecsi_lite/control.hh"

#include <chrono>
#include <stdexcept>
#include <string>
#include <utility>

namespace flecsph::sph {

/// The standard SPH control model for a state type deriving from simulation<D>, its actions named
/// as in the table above. The app registers its actions on "initial_data" (create_particles and
/// fill the fields), "output" and "finalize", may place more inside any point or the stage by
/// name (`m.action("force_evaluation", ...).after("forces")`, `m.action("advance", ...)
/// .before("kick")`), then calls execute(state).
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
  // The force evaluation, once for both points that run it.
  m.stage("force_evaluation");
  {
    auto search = on("force_evaluation", "search",
                     [](base& s) { update_neighbours(s, std::exchange(s.redistribute_next, false)); });
    auto density = on("force_evaluation", "density", update_density<D>);
    auto pressure = on("force_evaluation", "equation_of_state", update_pressure<D>);
    // The Cullen & Dehnen alpha (a no-op unless viscosity_switch = on).
    auto alpha =
      on("force_evaluation", "viscosity_switch", [](base& s) { update_viscosity_switch(s, s.initializing); });
    auto forces = on("force_evaluation", "forces", update_forces<D>);
    m.depends(density, search).depends(pressure, density).depends(alpha, pressure).depends(forces, alpha);
  }
  // initialize: the state at t = 0 and the first time step (a restart restored them all).
  {
    auto start = on("initialize", "start", [](base& s) {
      if (!s.particles) throw std::logic_error("sph: the initial_data point must create the particles");
      // A restart distributed and searched as the run it continues had (read_restart_checkpoint).
      if (s.restarted) return;
      if (s.physics.individual_time_steps()) start_timeline(s);  // every particle active at t = 0
      s.redistribute_next = true;                                // the first search distributes
    });
    auto evaluation = m.run_stage("initialize", "force_evaluation", [](const State& s) { return !s.restarted; });
    auto step = on("initialize", "first_time_step", [](base& s) {
      if (!s.restarted) choose_time_step(s, false);
    });
    auto diagnostics = on("initialize", "diagnostics", [](base& s) {
      conserved_diagnostics(s);
      s.started = std::chrono::steady_clock::now();
      s.started_step = s.step;
      s.started_time = s.time;
      s.initializing = false;
    });
    m.depends(evaluation, start).depends(step, evaluation).depends(diagnostics, step);
  }
  // advance: one kick-drift-kick step.
  {
    auto drift = on("advance", "kick_drift", first_kick_and_drift<D>);
    auto evaluation = m.run_stage("advance", "force_evaluation");
    auto kick = on("advance", "kick", second_kick<D>);
    auto clock = on("advance", "clock", [](base& s) { choose_time_step(s, true); });
    m.depends(evaluation, drift).depends(kick, evaluation).depends(clock, kick);
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
