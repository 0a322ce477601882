// rayleigh_taylor: the Rayleigh-Taylor instability (2D, periodic in x, walls at the bottom and
// top, uniform gravity -g along y) in the smooth set-up of Abel (2011) and Hopkins (2015), seeded
// by one mode of wavelength W; writes H5Part. The mode's growth rate is measured on the output by
// tests/validation/check_rayleigh_taylor.py against the linear theory of the set-up
// (rt_linear_theory.py).
//
//   mpirun -np 2 rayleigh_taylor apps/rayleigh_taylor/rayleigh_taylor.par [--set particles_per_side=128]
#include "rayleigh_taylor_problem.hh"
#include "uniform_gravity.hh"

#include "specialization/sph.hh"

#include "flecsi_lite/app.hh"
#include "flecsi_lite/runtime.hh"

namespace {
using namespace flecsi_lite;
namespace sph = flecsph::sph;

struct rayleigh_taylor_run : sph::app_state<2> {
  rayleigh_taylor::problem problem;
};

int run(const app::run_context& context) {
  rayleigh_taylor_run s;
  sph::configure(s, context);
  s.problem = rayleigh_taylor::problem_parameters().read(context.parameters());
  sph::require_equation_of_state(s.physics, flecsph::physics::eos_type::ideal_gas, s.program,
                                 "the hydrostatic equilibrium");
  if (s.physics.individual_time_steps())
    throw runtime::parameter_error(
      "rayleigh_taylor: time_steps = individual: the uniform gravity is added to every fluid particle at each force "
      "evaluation, which individual steps make only for the active ones; use time_steps = global");
  rayleigh_taylor::check_problem(s.problem, s.physics);
  // The set-up as root attributes: the growth-rate check computes its linear theory from them.
  const auto& p = s.problem;
  s.description = {{"width", p.width},
                   {"height", p.height},
                   {"rho1", p.rho1},
                   {"rho2", p.rho2},
                   {"uniform_gravity", p.gravity},
                   {"pressure", p.pressure},
                   {"smoothing", p.smoothing},
                   {"perturbation", p.perturbation}};
  auto m = sph::make_app_control_model<rayleigh_taylor_run>(
    {[](rayleigh_taylor_run& state) { rayleigh_taylor::set_domain(state, state.problem); },
     [](rayleigh_taylor_run& state) { rayleigh_taylor::create_particles(state, state.problem); }});
  m.action("force_evaluation", "uniform_gravity",
           [](rayleigh_taylor_run& state) {
             rayleigh_taylor::apply_uniform_gravity<2>(state, {0.0, -state.problem.gravity});
           })
    .after("forces");
  return context.execute(m, s, [](const rayleigh_taylor_run&) { return 0; });
}
}  // namespace

int main(int argc, char** argv) {
  sph::app_definition definition;
  definition.program = "rayleigh_taylor";
  definition.summary =
    "The Rayleigh-Taylor instability with SPH (2D, walls, uniform gravity; Abel 2011, Hopkins 2015): H5Part output.";
  definition.declare_parameters = [](runtime::parameter_schema& schema) {
    rayleigh_taylor::problem_parameters().declare(schema);
  };
  definition.physics_defaults.conductivity = 0;
  definition.run_defaults.end_time = 3.0;
  definition.run_defaults.progress_every = 100;
  definition.run_defaults.diagnostics_every = 100;
  definition.file_defaults.output_file = "rayleigh_taylor.h5part";
  definition.file_defaults.output_every = 0.1;
  definition.file_defaults.checkpoint_file = "rayleigh_taylor.checkpoint.h5part";
  definition.run = [](const app::run_context& context) { return run(context); };
  return sph::app_main(argc, argv, definition);
}
