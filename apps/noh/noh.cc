// noh: the Noh (1987) implosion (cold gas, gamma 5/3, speed 1 towards the centre) in 2D
// (cylindrical) or 3D (spherical) with the SPH specialization; writes H5Part. The shock radius,
// the post-shock density and the wall heating are measured on the output by
// tests/validation/check_noh.py (and drawn by plot_noh.py) against the exact solution.
//
//   mpirun -np 2 noh apps/noh/noh_2d.par [--set particles_per_side=128]
#include "noh_problem.hh"

#include "specialization/sph.hh"

#include "flecsi_lite/app.hh"
#include "flecsi_lite/runtime.hh"

#include <optional>

namespace {
using namespace flecsi_lite;
namespace sph = flecsph::sph;

template<int D>
struct noh_run : sph::app_state<D> {
  noh::problem problem;
  glass::layout_settings layout;  ///< initial_lattice = lattice (default) or glass
  std::optional<glass::tiling<D>> glass;
};

template<int D>
int run(const app::run_context& context) {
  noh_run<D> s;
  sph::configure(s, context);
  s.problem = noh::problem_parameters().read(context.parameters());
  s.layout = glass::layout_parameters().read(context.parameters());
  if (s.layout.layout == glass::start_layout::glass) glass::tiles_per_side(s.layout, s.problem.per_side, s.program);
  if (s.physics.eos.type != flecsph::physics::eos_type::ideal_gas)
    throw runtime::parameter_error("noh: the exact solution needs eos = ideal_gas");
  auto m = sph::make_app_control_model<noh_run<D>>(
    {[](noh_run<D>& state) { noh::set_open_domain(state, state.problem); },
     [](noh_run<D>& state) {
       state.glass = glass::choose_tiling<D>(state.layout, state.physics, state.problem.per_side, state.program);
       noh::create_lattice(state, state.problem, state.glass ? &*state.glass : nullptr);
     }});
  return context.execute(m, s, [](const noh_run<D>&) { return 0; });
}
}  // namespace

int main(int argc, char** argv) {
  sph::app_definition definition;
  definition.program = "noh";
  definition.summary = "The Noh implosion with SPH (2D cylindrical, 3D spherical): H5Part output.";
  definition.declare_parameters = [](runtime::parameter_schema& schema) {
    noh::problem_parameters().declare(schema);
    glass::layout_parameters().declare(schema);
  };
  definition.physics_defaults.conductivity = 0;
  definition.run_defaults.end_time = 0.6;
  definition.run_defaults.progress_every = 20;
  definition.run_defaults.diagnostics_every = 20;
  definition.file_defaults.output_file = "noh.h5part";
  definition.file_defaults.output_every = 0.2;
  definition.file_defaults.checkpoint_file = "noh.checkpoint.h5part";
  definition.run = [](const app::run_context& context) {
    return context.parameters().get<int>("dimension") == 2 ? run<2>(context) : run<3>(context);
  };
  return sph::app_main(argc, argv, definition);
}
