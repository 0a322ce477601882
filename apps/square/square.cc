// square: the square test (2D, periodic, gamma 5/3; Saitoh & Makino 2013) with the SPH
// specialization; writes H5Part. Whether the square keeps its corners and its density is measured
// on the output by tests/validation/check_square.py (and drawn by plot_square.py).
//
//   mpirun -np 2 square apps/square/square.par [--set particles_per_side=128] [--set conductivity_alpha=1]
#include "square_problem.hh"

#include "specialization/sph.hh"

#include "flecsi_lite/app.hh"
#include "flecsi_lite/runtime.hh"

namespace {
using namespace flecsi_lite;
namespace sph = flecsph::sph;

struct square_run : sph::app_state<2> {
  square::problem problem;
};

int run(const app::run_context& context) {
  square_run s;
  sph::configure(s, context);
  s.problem = square::problem_parameters().read(context.parameters());
  sph::require_equation_of_state(s.physics, flecsph::physics::eos_type::ideal_gas, s.program,
                                 "the pressure equilibrium");
  square::check_problem(s.problem, s.physics);
  const std::int64_t n = s.problem.per_side;
  // The first id of the square's particles (the checker tells the phases apart by it).
  s.description = {{"square_first_id", std::int64_t{n * n - (n / 2) * (n / 2)}}};
  auto m =
    sph::make_app_control_model<square_run>({[](square_run& state) { square::set_periodic_box(state, state.problem); },
                                             [](square_run& state) { square::create_lattices(state, state.problem); }});
  return context.execute(m, s, [](const square_run&) { return 0; });
}
}  // namespace

int main(int argc, char** argv) {
  sph::app_definition definition;
  definition.program = "square";
  definition.summary = "The square test with SPH (2D, periodic, density 4 in 1 at equal pressure): H5Part output.";
  definition.declare_parameters = [](runtime::parameter_schema& schema) {
    square::problem_parameters().declare(schema);
  };
  definition.physics_defaults.conductivity = 0;
  definition.run_defaults.end_time = 2.0;
  definition.run_defaults.progress_every = 100;
  definition.run_defaults.diagnostics_every = 100;
  definition.file_defaults.output_file = "square.h5part";
  definition.file_defaults.output_every = 0.5;
  definition.file_defaults.checkpoint_file = "square.checkpoint.h5part";
  definition.run = [](const app::run_context& context) { return run(context); };
  return sph::app_main(argc, argv, definition);
}
