// sod: the Sod (1978) shock tube with the SPH specialization: rho 1 / 0.125, P 1 / 0.1, gamma 1.4
// to t = 0.2 with equal-mass particles and fixed wall particles at both ends; writes H5Part and
// prints the L1 errors against the exact Riemann solution (Toro 2009, ch. 4).
//
//   mpirun -np 2 sod apps/sod/sod_1d.par [--set particles=2000] [--check-l1 0.005,0.005,0.02]
#include "sod_problem.hh"

#include "specialization/sph.hh"

#include "flecsi_lite/app.hh"
#include "flecsi_lite/runtime.hh"

#include <cmath>
#include <iomanip>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace {
using namespace flecsi_lite;
namespace sph = flecsph::sph;

template<int D>
struct sod_run : sph::app_state<D> {
  sod::problem problem;
  sod::l1_errors errors;
};

template<int D>
void report(sod_run<D>& s) {
  s.errors = sod::measure_l1_errors(s, s.problem);
  std::ostringstream line;
  line << std::scientific << std::setprecision(4) << "sod: L1 errors at t = " << s.time << " over " << s.errors.count
       << " particles with |x - " << s.problem.x_interface << "| < "
       << s.problem.window
       // 12 digits: plot_sod.py reports the same errors, app.sod.plot_l1_matches_app compares them to 1e-10.
       << ": density " << std::setprecision(11) << s.errors.rho << ", pressure " << s.errors.P << ", velocity "
       << s.errors.v;
  log::info() << line.str();
  log::info() << "sod: conserved at t = " << s.time << ": " << sph::describe_conserved(s.totals, s.initial_totals);
}

/// Exit status 1 when a requested check fails (bounds parsed at start-up by the frame).
template<int D>
int check(const sod_run<D>& s, const app::check_values& checks) {
  bool pass = true;
  if (checks.has("check-l1")) {
    const auto& bounds = checks.bounds("check-l1");
    const bool ok =
      s.errors.count > 0 && s.errors.rho <= bounds[0] && s.errors.P <= bounds[1] && s.errors.v <= bounds[2];
    if (!ok)
      log::error() << "sod: check failed: L1 errors (" << s.errors.rho << ", " << s.errors.P << ", " << s.errors.v
                   << ") exceed (" << bounds[0] << ", " << bounds[1] << ", " << bounds[2] << ")";
    pass = pass && ok;
  }
  if (checks.has("check-conservation")) {
    const auto& bounds = checks.bounds("check-conservation");
    const double momentum = std::fabs(s.totals.momentum[0] - s.initial_totals.momentum[0]);
    const double energy = std::fabs(s.totals.total - s.initial_totals.total) / std::fabs(s.initial_totals.total);
    const bool mass = s.totals.mass == s.initial_totals.mass;
    log::info() << std::scientific << std::setprecision(3) << "sod: momentum change " << momentum
                << ", relative energy change " << energy << ", mass " << (mass ? "exact" : "CHANGED");
    const bool ok = mass && momentum <= bounds[0] && energy <= bounds[1];
    if (!ok) log::error() << "sod: conservation check failed (bounds " << bounds[0] << ", " << bounds[1] << ")";
    pass = pass && ok;
  }
  return pass ? 0 : 1;
}

template<int D>
int run(const app::run_context& context) {
  sod_run<D> s;
  sph::configure(s, context);
  s.problem = sod::problem_parameters().read(context.parameters());
  sph::require_equation_of_state(s.physics, flecsph::physics::eos_type::ideal_gas, s.program, "the exact solution");
  auto m =
    sph::make_app_control_model<sod_run<D>>({[](sod_run<D>& state) { sod::set_tube_domain(state, state.problem); },
                                             [](sod_run<D>& state) { sod::create_tube(state, state.problem); }});
  m.action("finalize", "report", report<D>);
  return context.execute(m, s, [&context](const sod_run<D>& state) { return check(state, context.checks()); });
}
}  // namespace

int main(int argc, char** argv) {
  sph::app_definition definition;
  definition.program = "sod";
  definition.summary = "The Sod shock tube with SPH: H5Part output and L1 errors against the exact solution.";
  definition.declare_parameters = [](runtime::parameter_schema& schema) { sod::problem_parameters().declare(schema); };
  // Without a parameter file: the standard problem of apps/sod/sod_1d.par (validation.defaults.sod).
  definition.physics_defaults.eos.ideal.gamma = 1.4;
  definition.run_defaults.end_time = 0.2;
  definition.run_defaults.progress_every = 200;
  definition.run_defaults.diagnostics_every = 200;
  definition.file_defaults.output_file = "sod.h5part";
  definition.file_defaults.output_every = 0.05;
  definition.file_defaults.checkpoint_file = "sod.checkpoint.h5part";
  definition.checks = {
    {"check-l1", {"RHO", "P", "V"}, "exit with status 1 if an L1 error exceeds its bound"},
    {"check-conservation",
     {"DP", "DE"},
     "exit with status 1 unless mass is exact, |momentum change| <= DP and |energy change|/E <= DE"}};
  definition.run = [](const app::run_context& context) {
    const auto& p = context.parameters();
    const int dimension = p.get<int>("dimension");
    return dimension == 1 ? run<1>(context) : dimension == 2 ? run<2>(context) : run<3>(context);
  };
  return sph::app_main(argc, argv, definition);
}
