// heat: the example specialization of flecsi_lite, to copy when writing a new one. It solves
// u_t = kappa u_xx on a distributed 1-D mesh with the control model (initialize, a cycle of
// advance and analyze, finalize), tasks with field privileges, ghost copies and reductions, and
// its parameter keys declared once on the framework's app frame.
//
//   mpirun -np 2 heat --cells 4096 --time 0.01 [--check 1e-5] [--trace trace.json]
//   mpirun -np 2 heat run.par --set kappa=0.5         # heat --parameters-help lists the keys
#include "heat_tasks.hh"

#include "flecsi_lite/app.hh"
#include "flecsi_lite/control.hh"
#include "flecsi_lite/runtime.hh"

#include <chrono>
#include <cstdio>
#include <iomanip>
#include <memory>
#include <string>

namespace {
using namespace flecsi_lite;

/// The parameters of a run, each a key of the parameter file (heat_parameters).
struct heat_settings {
  std::size_t cells = 4096;
  double kappa = 1;  ///< diffusivity
  double end_time = 0.002;
  int analyze_every = 200;  ///< steps between diagnostics
};

runtime::parameter_block<heat_settings> heat_parameters() {
  runtime::parameter_block<heat_settings> heat;
  heat.integer("cells", &heat_settings::cells, "number of cells").at_least(2);
  heat.real("kappa", &heat_settings::kappa, "diffusivity").greater_than(0);
  heat.real("end_time", &heat_settings::end_time, "end time").greater_than(0);
  heat.integer("analyze_every", &heat_settings::analyze_every, "steps between diagnostics").at_least(1);
  return heat;
}

struct simulation : heat_settings {
  double courant = 0.4;
  std::unique_ptr<heat::mesh> mesh;
  double time = 0, dt = 0;
  long step = 0;
  double initial_heat = 0, error = 0, heat_drift = 0;
  std::chrono::steady_clock::time_point start;
};

void create_mesh(simulation& s) {
  s.mesh = std::make_unique<heat::mesh>(s.cells, 1, true);
  const double dx = 1.0 / s.cells;
  s.dt = s.courant * dx * dx / s.kappa;
}

void initial_condition(simulation& s) {
  auto& m = *s.mesh;
  execute<heat::initialize>(m, heat::temperature(m));
  s.initial_heat = reduce<heat::total_heat, reduction::exact_sum>(m, heat::temperature(m)).get();
  s.start = std::chrono::steady_clock::now();
  log::info() << "heat: " << s.cells << " cells on " << runtime::size() << " rank(s), kappa " << s.kappa << ", dt "
              << s.dt << ", until t = " << s.end_time;
}

void diffuse(simulation& s) {
  auto& m = *s.mesh;
  const double courant = s.kappa * s.dt * s.cells * s.cells;
  execute<heat::diffuse>(m, heat::temperature(m), heat::next_temperature(m), courant);
  execute<heat::copy>(heat::next_temperature(m), heat::temperature(m));
  s.time += s.dt;
  ++s.step;
}

void analyze(simulation& s) {
  const bool last = s.time + s.dt > s.end_time;
  if (s.step % s.analyze_every && !last) return;
  auto& m = *s.mesh;
  auto error = reduce<heat::max_error, reduction::max>(m, heat::temperature(m), s.time, s.kappa);
  auto total = reduce<heat::total_heat, reduction::exact_sum>(m, heat::temperature(m));
  s.error = error.get();
  s.heat_drift = std::abs(total.get() - s.initial_heat);
  const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - s.start).count();
  const double fraction = s.time / s.end_time;
  log::info() << "step " << std::setw(6) << s.step << "  t " << std::setw(10) << s.time << "  dt " << s.dt << "  "
              << std::setw(5) << std::fixed << std::setprecision(1) << 100 * fraction << "%" << std::defaultfloat
              << std::setprecision(6) << "  ETA " << elapsed * (1 - fraction) / fraction << " s  "
              << s.cells * s.step / elapsed << " cell-steps/s  max error " << s.error << "  heat drift "
              << s.heat_drift;
}

void report(simulation& s) {
  log::info() << "heat: done after " << s.step << " steps; max error against the exact solution " << s.error
              << ", total heat drift " << s.heat_drift;
}

control::control_model<simulation> make_control_model() {
  control::control_model<simulation> m;
  m.point("initialize")
    .cycle("evolve", {"advance", "analyze"}, [](const simulation& s) { return s.time + s.dt <= s.end_time; })
    .point("finalize");
  auto mesh = m.action("initialize", "create_mesh", create_mesh);
  auto initial = m.action("initialize", "initial_condition", initial_condition);
  m.depends(initial, mesh);
  m.action("advance", "diffuse", diffuse);
  m.action("analyze", "analyze", analyze);
  m.action("finalize", "report", report);
  return m;
}
}  // namespace

int main(int argc, char** argv) {
  app::definition heat;
  heat.program = "heat";
  heat.summary = "Explicit heat diffusion on a distributed 1-D mesh: the flecsi_lite example.";
  heat.declare_parameters = [](runtime::parameter_schema& schema) { heat_parameters().declare(schema); };
  // The options of the first versions, each the --set of its key.
  heat.option_keys = {{"cells", "cells"}, {"kappa", "kappa"}, {"time", "end_time"}, {"analyze-every", "analyze_every"}};
  // Parsed by the frame at start-up: a bad TOL is exit status 2 before anything runs.
  heat.checks = {{"check", {"TOL"}, "exit with status 1 if the final max error exceeds TOL or the heat drifts"}};
  heat.run = [](const app::run_context& context) {
    const double tolerance = context.checks().has("check") ? context.checks().bound("check") : -1;
    simulation s;
    static_cast<heat_settings&>(s) = heat_parameters().read(context.parameters());
    return context.execute(make_control_model(), s, [tolerance](const simulation& state) {
      if (tolerance < 0) return 0;
      const bool pass = state.error <= tolerance && state.heat_drift <= 1e-12;
      if (!pass) log::error() << "heat: check failed: error " << state.error << " > " << tolerance;
      return pass ? 0 : 1;
    });
  };
  return app::main(argc, argv, heat);
}
