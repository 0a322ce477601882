// kelvin_helmholtz: the Kelvin-Helmholtz instability (2D, periodic, gamma 5/3) in the smooth
// set-up of McNally, Lyra & Passy (2012) with the SPH specialization; writes H5Part. The mode
// amplitude (their eqs. 4-7) and its linear growth rate against the linear theory of the profile
// (kh_linear_theory.py) are measured on the output by tests/validation/check_kelvin_helmholtz.py.
//
//   mpirun -np 2 kelvin_helmholtz apps/kelvin_helmholtz/kelvin_helmholtz.par [--set particles_per_side=128]
#include "kelvin_helmholtz_problem.hh"

#include "specialization/sph.hh"

#include "flecsi_lite/app.hh"
#include "flecsi_lite/runtime.hh"

namespace {
using namespace flecsi_lite;
namespace sph = flecsph::sph;

struct kelvin_helmholtz_run : sph::app_state<2> {
  kelvin_helmholtz::problem problem;
};

int run(const app::run_context& context) {
  kelvin_helmholtz_run s;
  sph::configure(s, context);
  s.problem = kelvin_helmholtz::problem_parameters().read(context.parameters());
  sph::require_equation_of_state(s.physics, flecsph::physics::eos_type::ideal_gas, s.program,
                                 "the pressure equilibrium");
  kelvin_helmholtz::check_problem(s.problem, s.physics);
  auto m = sph::make_app_control_model<kelvin_helmholtz_run>(
    {[](kelvin_helmholtz_run& state) { kelvin_helmholtz::set_periodic_box(state, state.problem); },
     [](kelvin_helmholtz_run& state) { kelvin_helmholtz::create_particles(state, state.problem); }});
  return context.execute(m, s, [](const kelvin_helmholtz_run&) { return 0; });
}
}  // namespace

int main(int argc, char** argv) {
  sph::app_definition definition;
  definition.program = "kelvin_helmholtz";
  definition.summary = "The Kelvin-Helmholtz instability with SPH (2D, McNally et al. 2012): H5Part output.";
  definition.declare_parameters = [](runtime::parameter_schema& schema) {
    kelvin_helmholtz::problem_parameters().declare(schema);
  };
  definition.physics_defaults.conductivity = 0;
  definition.run_defaults.end_time = 2.0;
  definition.run_defaults.progress_every = 100;
  definition.run_defaults.diagnostics_every = 100;
  definition.file_defaults.output_file = "kelvin_helmholtz.h5part";
  definition.file_defaults.output_every = 0.05;
  definition.file_defaults.checkpoint_file = "kelvin_helmholtz.checkpoint.h5part";
  definition.run = [](const app::run_context& context) { return run(context); };
  return sph::app_main(argc, argv, definition);
}
