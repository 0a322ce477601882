// cold_collapse: the pressureless collapse of a uniform sphere (M = R = G = 1) with SPH and
// self-gravity; the radius holding a fraction of the mass is compared at every step with free
// fall up to a fraction of t_ff = (pi / 2) sqrt(R^3 / (2 G M)).
//
//   mpirun -np 2 cold_collapse apps/cold_collapse/cold_collapse.par [--check-radius 0.03]
#include "cold_collapse_problem.hh"

#include "specialization/sph.hh"

#include "flecsi_lite/app.hh"
#include "flecsi_lite/runtime.hh"

#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>

namespace {
using namespace flecsi_lite;
namespace sph = flecsph::sph;

struct cold_collapse_run : sph::app_state<3> {
  cold_collapse::problem problem;
  double gravitational_constant = 1;
  double free_fall_time = 0;
  double initial_radius = 0;  ///< of the generated sphere, holding radius_mass_fraction of the mass
  double largest_error = 0;   ///< max over the compared steps of |r / (r0 x(t)) - 1|
  double largest_error_time = 0;
  double last_radius = 0, last_time = 0;  ///< the last compared step
  double last_expected = 0;
};

/// The radius of the generated sphere (so that a restart compares with the same r0).
void initial_radius(cold_collapse_run& s) {
  const auto sites = spheres::ball_lattice(s.problem.particles);
  s.initial_radius = s.problem.radius * spheres::fraction_radius(sites, s.problem.mass_fraction);
  s.free_fall_time = cold_collapse::free_fall_time(s.problem, s.gravitational_constant);
}

/// After every step up to compare_until t_ff: the radius against free fall.
void compare_radius(cold_collapse_run& s) {
  const double tau = s.time / s.free_fall_time;
  if (tau > s.problem.compare_until * (1 + 1e-12)) return;
  const double radius = spheres::mass_fraction_radius(s, s.problem.mass_fraction);
  const double expected = s.initial_radius * cold_collapse::free_fall_radius(tau);
  const double error = std::fabs(radius / expected - 1);
  if (error > s.largest_error) {
    s.largest_error = error;
    s.largest_error_time = s.time;
  }
  s.last_radius = radius;
  s.last_expected = expected;
  s.last_time = s.time;
}

void report(cold_collapse_run& s) {
  std::ostringstream line;
  line << std::setprecision(5) << "cold_collapse: the radius holding " << s.problem.mass_fraction
       << " of the mass, r0 = " << s.initial_radius << ", at t = " << s.last_time << " = "
       << s.last_time / s.free_fall_time << " t_ff (t_ff = " << s.free_fall_time << "): " << s.last_radius
       << ", free fall " << s.last_expected << "; largest |r / r_free_fall - 1| up to " << s.problem.compare_until
       << " t_ff: " << s.largest_error << " at t = " << s.largest_error_time;
  log::info() << line.str();
}

/// Exit status 1 when --check-radius TOL fails.
int check(const cold_collapse_run& s, const app::check_values& checks) {
  if (!checks.has("check-radius")) return 0;
  const double bound = checks.bound("check-radius");
  const bool reached = s.last_time >= s.problem.compare_until * s.free_fall_time * (1 - 1e-12) ||
                       s.time >= s.problem.compare_until * s.free_fall_time;
  const bool pass = reached && s.largest_error <= bound;
  if (!reached)
    log::error() << "cold_collapse: check failed: the run ended at t = " << s.time
                 << " before compare_until = " << s.problem.compare_until
                 << " t_ff = " << s.problem.compare_until * s.free_fall_time;
  else if (!pass)
    log::error() << "cold_collapse: check failed: |r / r_free_fall - 1| reached " << s.largest_error
                 << " at t = " << s.largest_error_time << " (bound " << bound << ")";
  return pass ? 0 : 1;
}

int run(const app::run_context& context) {
  cold_collapse_run s;
  sph::configure(s, context);
  s.problem = cold_collapse::problem_parameters().read(context.parameters());
  if (!s.physics.gravity.enabled) throw runtime::parameter_error("cold_collapse: the collapse needs gravity = true");
  s.gravitational_constant = s.physics.gravity.constant;
  auto m = sph::make_app_control_model<cold_collapse_run>(
    {[](cold_collapse_run& state) {
       cold_collapse::check_problem(state.problem, state.physics, state.gravitational_constant);
     },
     [](cold_collapse_run& state) {
       cold_collapse::create_sphere(state, state.problem, state.gravitational_constant);
     }});
  m.action("initialize", "initial_radius",
           [](cold_collapse_run& state) {
             initial_radius(state);
             compare_radius(state);
           })
    .after("diagnostics");
  m.action("analyze", "radius_check", compare_radius).after("conserved_quantities");
  m.action("finalize", "report", report);
  return context.execute(m, s, [&context](const cold_collapse_run& state) { return check(state, context.checks()); });
}
}  // namespace

int main(int argc, char** argv) {
  sph::app_definition definition;
  definition.program = "cold_collapse";
  definition.summary = "The cold collapse of a uniform sphere with SPH and self-gravity: the radius against free fall.";
  definition.declare_parameters = [](runtime::parameter_schema& schema) {
    cold_collapse::problem_parameters().declare(schema);
  };
  // Without a parameter file: the problem of apps/cold_collapse/cold_collapse.par.
  definition.physics_defaults.eos.ideal.gamma = 5.0 / 3.0;
  definition.physics_defaults.conductivity = 0;
  definition.physics_defaults.gravity.enabled = true;
  // No shocks before t_ff: the viscosity would act on every approaching pair of the homologous
  // collapse, and its one-sided force at the surface, ~ 2 beta (h / r) (1 - x) of gravity, brakes it.
  definition.physics_defaults.viscosity.alpha = 0;
  definition.physics_defaults.viscosity.beta = 0;
  definition.run_defaults.end_time = 1.0;
  definition.run_defaults.progress_every = 100;
  definition.run_defaults.diagnostics_every = 100;
  definition.file_defaults.output_file = "cold_collapse.h5part";
  definition.file_defaults.output_every = 0.1;
  definition.file_defaults.checkpoint_file = "cold_collapse.checkpoint.h5part";
  definition.checks = {
    {"check-radius", {"TOL"}, "exit with status 1 if |r / r_free_fall - 1| exceeds TOL up to compare_until t_ff"}};
  definition.run = [](const app::run_context& context) { return run(context); };
  return sph::app_main(argc, argv, definition);
}
