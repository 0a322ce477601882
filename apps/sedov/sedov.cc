// sedov: the Sedov-Taylor blast wave (energy 1 at the centre of a uniform cold medium, gamma 5/3)
// in 2D or 3D with the SPH specialization; writes H5Part and compares the shock radius and the
// energy with the similarity solution (Sedov 1959; Kamm & Timmes 2007).
//
//   mpirun -np 2 sedov apps/sedov/sedov_3d.par [--set particles_per_side=64] [--check 0.05,1e-3]
#include "sedov_problem.hh"

#include "specialization/sph.hh"

#include "flecsi_lite/app.hh"
#include "flecsi_lite/runtime.hh"

#include <cmath>
#include <iomanip>
#include <optional>
#include <sstream>
#include <stdexcept>
#include <string>

namespace {
using namespace flecsi_lite;
namespace sph = flecsph::sph;

template<int D>
struct sedov_run : sph::app_state<D> {
  sedov::problem problem;
  glass::layout_settings layout;  ///< initial_lattice = lattice (default) or glass
  std::optional<glass::tiling<D>> glass;
  sedov::blast_comparison blast;
};

template<int D>
void report(sedov_run<D>& s) {
  s.blast = sedov::compare_with_sedov_taylor(s, s.problem);
  std::ostringstream line;
  // 12 digits: plot_sedov.py reports the same comparison, apps.sedov.plot_matches_app compares them.
  line << std::setprecision(12) << "sedov: at t = " << s.time
       << " the shock front (half height) is at r = " << s.blast.front_radius << ", Sedov-Taylor shock radius "
       << s.blast.shock_radius << ", relative difference " << s.blast.relative_error()
       << "; the density peaks at r = " << s.blast.peak_radius << " (mean " << s.blast.peak_density << "; strong shock "
       << s.blast.analytic_peak << "); relative energy change "
       << (s.totals.total - s.initial_totals.total) / s.initial_totals.total;
  log::info() << line.str();
}

/// Exit status 1 when --check DR,DE fails.
template<int D>
int check(const sedov_run<D>& s, const app::check_values& checks) {
  if (!checks.has("check")) return 0;
  const double radius_bound = checks.bounds("check")[0], energy_bound = checks.bounds("check")[1];
  const double energy = std::fabs(s.totals.total - s.initial_totals.total) / s.initial_totals.total;
  const bool pass = std::fabs(s.blast.relative_error()) <= radius_bound && energy <= energy_bound;
  if (!pass)
    log::error() << "sedov: check failed (bounds: radius " << radius_bound << ", energy " << energy_bound << ")";
  return pass ? 0 : 1;
}

template<int D>
int run(const app::run_context& context) {
  sedov_run<D> s;
  sph::configure(s, context);
  s.problem = sedov::problem_parameters().read(context.parameters());
  s.layout = glass::layout_parameters().read(context.parameters());
  if (s.layout.layout == glass::start_layout::glass) glass::tiles_per_side(s.layout, s.problem.per_side, s.program);
  sph::require_equation_of_state(s.physics, flecsph::physics::eos_type::ideal_gas, s.program,
                                 "the similarity solution");
  auto m = sph::make_app_control_model<sedov_run<D>>(
    {[](sedov_run<D>& state) { sedov::set_periodic_box(state, state.problem); },
     [](sedov_run<D>& state) {
       state.glass = glass::choose_tiling<D>(state.layout, state.physics, state.problem.per_side, state.program);
       sedov::create_lattice(state, state.problem, state.glass ? &*state.glass : nullptr);
     }});
  m.action("finalize", "report", report<D>);
  return context.execute(m, s, [&context](const sedov_run<D>& state) { return check(state, context.checks()); });
}
}  // namespace

int main(int argc, char** argv) {
  sph::app_definition definition;
  definition.program = "sedov";
  definition.summary =
    "The Sedov-Taylor blast wave with SPH: H5Part output and the shock radius against the "
    "similarity solution.";
  definition.declare_parameters = [](runtime::parameter_schema& schema) {
    sedov::problem_parameters().declare(schema);
    glass::layout_parameters().declare(schema);
  };
  // Without a parameter file: the problem of apps/sedov/sedov_3d.par (validation.defaults.sedov).
  definition.physics_defaults.conductivity = 0;
  definition.run_defaults.end_time = 0.05;
  definition.run_defaults.progress_every = 10;
  definition.run_defaults.diagnostics_every = 10;
  definition.file_defaults.output_file = "sedov.h5part";
  definition.file_defaults.output_every = 0.01;
  definition.file_defaults.checkpoint_file = "sedov.checkpoint.h5part";
  definition.checks = {
    {"check", {"DR", "DE"}, "exit with status 1 unless |shock radius error| <= DR and |energy change|/E <= DE"}};
  definition.run = [](const app::run_context& context) {
    const auto& p = context.parameters();
    return p.get<int>("dimension") == 2 ? run<2>(context) : run<3>(context);
  };
  return sph::app_main(argc, argv, definition);
}
