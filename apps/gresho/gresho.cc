// gresho: the Gresho-Chan vortex (2D, periodic, gamma 5/3) with the SPH specialization; writes
// H5Part. The binned L1 error of v_phi against the steady exact vortex is measured on the output
// by tests/validation/check_gresho.py (and drawn by plot_gresho.py).
//
//   mpirun -np 2 gresho apps/gresho/gresho.par [--set particles_per_side=128] [--set viscosity_switch=on]
#include "gresho_problem.hh"

#include "specialization/sph.hh"

#include "flecsi_lite/app.hh"
#include "flecsi_lite/runtime.hh"

namespace {
using namespace flecsi_lite;
namespace sph = flecsph::sph;

struct gresho_run : sph::app_state<2> {
  gresho::problem problem;
};

int run(const app::run_context& context) {
  gresho_run s;
  sph::configure(s, context);
  s.problem = gresho::problem_parameters().read(context.parameters());
  if (s.physics.eos.type != flecsph::physics::eos_type::ideal_gas)
    throw runtime::parameter_error("gresho: the vortex needs eos = ideal_gas");
  auto m =
    sph::make_app_control_model<gresho_run>({[](gresho_run& state) { gresho::set_periodic_box(state, state.problem); },
                                             [](gresho_run& state) { gresho::create_lattice(state, state.problem); }});
  return context.execute(m, s, [](const gresho_run&) { return 0; });
}
}  // namespace

int main(int argc, char** argv) {
  sph::app_definition definition;
  definition.program = "gresho";
  definition.summary = "The Gresho-Chan vortex with SPH (2D, periodic): H5Part output.";
  definition.declare_parameters = [](runtime::parameter_schema& schema) {
    gresho::problem_parameters().declare(schema);
  };
  definition.physics_defaults.conductivity = 0;
  definition.run_defaults.end_time = 1.0;
  definition.run_defaults.progress_every = 50;
  definition.run_defaults.diagnostics_every = 50;
  definition.file_defaults.output_file = "gresho.h5part";
  definition.file_defaults.output_every = 0.5;
  definition.file_defaults.checkpoint_file = "gresho.checkpoint.h5part";
  definition.run = [](const app::run_context& context) { return run(context); };
  return sph::app_main(argc, argv, definition);
}
