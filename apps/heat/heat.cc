// heat: the example specialization of flecsi_lite, to copy when writing a new one. It solves
// u_t = kappa u_xx on a distributed 1-D mesh with the control model (initialize, a cycle of
// advance and analyze, finalize), tasks with field privileges, ghost copies and reductions.
//
//   mpirun -np 2 heat --cells 4096 --time 0.01 [--check 1e-5] [--trace trace.json]
#include "heat_tasks.hh"

#include "flecsi_lite/control.hh"
#include "flecsi_lite/runtime.hh"

#include <chrono>
#include <cstdio>
#include <iomanip>
#include <memory>

namespace {
using namespace flecsi_lite;

struct simulation {
  std::size_t cells;
  double kappa, end_time, courant = 0.4, check_tolerance = -1;
  int analyze_every;
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
  log::info() << "heat: " << s.cells << " cells on " << runtime::size() << " rank(s), kappa " << s.kappa
              << ", dt " << s.dt << ", until t = " << s.end_time;
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
  log::info() << "step " << std::setw(6) << s.step << "  t " << std::setw(10) << s.time << "  dt " << s.dt
              << "  " << std::setw(5) << std::fixed << std::setprecision(1) << 100 * fraction << "%"
              << std::defaultfloat << std::setprecision(6) << "  ETA " << elapsed * (1 - fraction) / fraction
              << " s  " << s.cells * s.step / elapsed << " cell-steps/s  max error " << s.error
              << "  heat drift " << s.heat_drift;
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
} // namespace

int main(int argc, char** argv) {
  runtime::options options("Explicit heat diffusion on a distributed 1-D mesh: the flecsi_lite example.");
  options.value("cells", "N", "number of cells", "4096")
    .value("kappa", "K", "diffusivity", "1")
    .value("time", "T", "end time", "0.002")
    .value("analyze-every", "N", "steps between diagnostics", "200")
    .value("check", "TOL", "exit with status 1 if the final max error exceeds TOL");
  runtime::runtime rt(argc, argv, options);
  if (!rt.proceed()) return rt.exit_code();
  simulation s;
  try {
    s.cells = std::stoul(rt.opts().get("cells"));
    s.kappa = std::stod(rt.opts().get("kappa"));
    s.end_time = std::stod(rt.opts().get("time"));
    s.analyze_every = std::stoi(rt.opts().get("analyze-every"));
    if (rt.opts().has("check")) s.check_tolerance = std::stod(rt.opts().get("check"));
    if (s.cells < 2 || s.kappa <= 0 || s.end_time <= 0 || s.analyze_every < 1)
      throw std::invalid_argument("cells >= 2, kappa > 0, time > 0 and analyze-every >= 1 are required");
  } catch (const std::exception& e) {
    log::error() << "heat: bad option value: " << e.what();
    return 2;
  }
  const int status = make_control_model().execute(s);
  if (status || s.check_tolerance < 0) return status;
  const bool pass = s.error <= s.check_tolerance && s.heat_drift <= 1e-12;
  if (!pass) log::error() << "heat: check failed: error " << s.error << " > " << s.check_tolerance;
  return pass ? 0 : 1;
}
