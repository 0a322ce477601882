// Chapter 6: a new SPH problem on the SPH specialization, with a task of its own inserted in the
// step. A uniform gas at rest in a periodic box cools towards a floor energy, du/dt = -(u - u_floor)
// / t_cool (Newtonian cooling): the uniform state has no pressure gradients, so the gas stays at
// rest and u follows u_floor + (u0 - u_floor) exp(-t / t_cool), which the program checks at the end.
//
//   mpirun -np 2 tutorial_6_sph_problem [--set cooling_time=0.1] [--set particles_per_side=48]
#include "specialization/sph.hh"

#include "flecsi_lite/app.hh"
#include "flecsi_lite/execution.hh"
#include "flecsi_lite/io.hh"
#include "flecsi_lite/runtime.hh"

#include <algorithm>
#include <cmath>

namespace {
using namespace flecsi_lite;
namespace sph = flecsph::sph;
constexpr int D = 2;
using f = sph::fields<D>;

/// The problem's keys live in a struct; each is declared once, next to its member.
struct problem {
  std::int64_t per_side = 32;  ///< lattice particles per side of the unit box
  double u0 = 1.0, u_floor = 0.25, cooling_time = 0.2;
};
const runtime::parameter_block<problem>& problem_parameters() {
  static const auto block = [] {
    runtime::parameter_block<problem> b;
    b.integer("particles_per_side", &problem::per_side, "lattice particles per side").at_least(8);
    b.real("u0", &problem::u0, "initial specific internal energy").greater_than(0);
    b.real("u_floor", &problem::u_floor, "energy the gas cools towards").at_least(0);
    b.real("cooling_time", &problem::cooling_time, "e-folding time of the cooling").greater_than(0);
    return b;
  }();
  return block;
}

/// The state: the SPH app state plus the problem.
struct cooling_run : sph::app_state<D> {
  problem gas;
};

/// This rank's block of a square lattice in the periodic unit box.
void create_lattice(cooling_run& s) {
  const auto n = static_cast<std::uint64_t>(s.gas.per_side);
  const auto block = io::block_slice(n * n, runtime::rank(), runtime::size());
  sph::create_particles(s, block.count);
  const double spacing = 1.0 / double(n);
  sph::initial_fields(s, [&](std::size_t i, sph::initial_particle<D>& p) {
    const std::uint64_t index = block.offset + i;
    p.x = {(double(index % n) + 0.5) * spacing, (double(index / n) + 0.5) * spacing};
    p.id = index;
    p.m = spacing * spacing;  // density 1
    p.h = s.physics.eta * spacing;
    p.rho = 1.0;
    p.u = s.gas.u0;
  });
}

/// The new task: adds the cooling rate to du/dt, which "forces" has just computed (sph::ro and
/// sph::rw say what it reads and writes; the executor orders it after forces by those privileges).
void cool(problem gas, sph::ro<double> u, sph::rw<double> du_dt) {
  forall(
    u.size(), [&](std::size_t a) { du_dt(a) -= (u(a) - gas.u_floor) / gas.cooling_time; }, "cooling");
}
void cooling_action(cooling_run& s) {
  execute<cool>(s.gas, f::internal_energy(*s.particles), f::internal_energy_rate(*s.particles));
}

/// Largest |u - expected| over this rank's particles (reduced with max over the ranks).
double largest_deviation(double expected, sph::ro<double> u) {
  double worst = 0;
  for (std::size_t a = 0; a < u.size(); ++a) worst = std::max(worst, std::fabs(u(a) - expected));
  return worst;
}

/// Exit status 1 unless every particle's u follows the exponential (the leapfrog's error is
/// second order in dt / t_cool: 1.5e-4 of u0 - u_floor at the default settings) and the gas
/// stayed at rest.
int check(const cooling_run& s) {
  const problem& g = s.gas;
  const double expected = g.u_floor + (g.u0 - g.u_floor) * std::exp(-s.time / g.cooling_time);
  const double deviation =
    reduce<largest_deviation, reduction::max>(expected, f::internal_energy(*s.particles)).get() / (g.u0 - g.u_floor);
  log::info() << "cooling: at t = " << s.time << " u = " << expected << " expected; largest deviation " << deviation
              << " of u0 - u_floor, kinetic energy " << s.totals.kinetic;
  return deviation < 1e-3 && s.totals.kinetic < 1e-20 ? 0 : 1;
}

int run(const app::run_context& context) {
  cooling_run s;
  sph::configure(s, context);  // physics, run control, files
  s.gas = problem_parameters().read(context.parameters());
  auto m =
    sph::make_app_control_model<cooling_run>({[](cooling_run& r) {
                                                r.tree_settings.fixed_box = topology::ntree::box<D>{{0, 0}, {1, 1}};
                                                r.tree_settings.periodic.fill(true);
                                              },
                                              create_lattice});
  // One line: the cooling rate joins du/dt right after the forces, before the kick uses it, in
  // the force evaluation, which runs at the start (initialize) and in every step (advance).
  m.action("force_evaluation", "cooling", cooling_action).after("forces");
  return context.execute(m, s, check);
}
}  // namespace

int main(int argc, char** argv) {
  sph::app_definition definition;
  definition.program = "cooling";
  definition.summary = "A uniform gas cooling towards a floor energy (tutorial chapter 6).";
  definition.declare_parameters = [](runtime::parameter_schema& schema) { problem_parameters().declare(schema); };
  definition.run_defaults.end_time = 0.4;
  definition.run_defaults.progress_every = 0;
  definition.run_defaults.diagnostics_every = 0;
  definition.file_defaults.output_file = "cooling.h5part";
  definition.run = run;
  return sph::app_main(argc, argv, definition);
}
