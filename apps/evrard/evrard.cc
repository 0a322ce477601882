// evrard: the Evrard (1988) adiabatic collapse of a cold gas sphere (rho ~ 1/r, u = 0.05 G M / R,
// gamma 5/3) with SPH and self-gravity; writes H5Part and the energies K, U, W, E per step in the
// statistics file, and checks the conservation of E = K + U + W.
//
//   mpirun -np 2 evrard apps/evrard/evrard.par [--set particles=50000] [--check-energy 0.01]
#include "evrard_problem.hh"

#include "specialization/sph.hh"

#include "flecsi_lite/app.hh"
#include "flecsi_lite/runtime.hh"

#include <cmath>
#include <iomanip>
#include <sstream>
#include <stdexcept>
#include <string>

namespace {
using namespace flecsi_lite;
namespace sph = flecsph::sph;

struct evrard_run : sph::app_state<3> {
  evrard::problem problem;
  double gravitational_constant = 1;
  double largest_energy_error = 0;  ///< max over the steps of |E - E0| / |E0|
  double largest_error_time = 0;
};

/// At every step whose totals the run measured (its statistics rows, every statistics_every steps,
/// and its conserved lines): |E - E0| / |E0| with E = K + U + W. Between them no step measures
/// the potential energy of every particle (with individual time steps the inactive particles'
/// gravity is walked only for such steps: step/gravity.hh).
void track_energy(evrard_run& s) {
  if (s.totals_step != s.step) return;
  const auto& totals = s.totals;
  const double error = std::fabs(totals.total - s.initial_totals.total) / std::fabs(s.initial_totals.total);
  if (error > s.largest_energy_error) {
    s.largest_energy_error = error;
    s.largest_error_time = s.time;
  }
}

void report(evrard_run& s) {
  const auto analytic = evrard::analytic_energies(s.problem, s.gravitational_constant);
  std::ostringstream line;
  line << std::setprecision(6) << "evrard: t = " << s.time << ": K = " << s.totals.kinetic
       << ", U = " << s.totals.internal << ", W = " << s.totals.potential << ", E = " << s.totals.total
       << "; E0 = " << s.initial_totals.total << " (W0 = " << s.initial_totals.potential
       << "; continuous sphere: W0 = " << analytic.potential << ", E0 = " << analytic.total()
       << "); largest |E - E0| / |E0| = " << std::scientific << std::setprecision(3) << s.largest_energy_error
       << " at t = " << std::defaultfloat << s.largest_error_time;
  log::info() << line.str();
}

/// Exit status 1 when --check-energy TOL fails.
int check(const evrard_run& s, const app::check_values& checks) {
  if (!checks.has("check-energy")) return 0;
  const double bound = checks.bound("check-energy");
  const bool pass = s.largest_energy_error <= bound;
  if (!pass)
    log::error() << "evrard: check failed: |E - E0| / |E0| reached " << s.largest_energy_error
                 << " at t = " << s.largest_error_time << " (bound " << bound << ")";
  return pass ? 0 : 1;
}

int run(const app::run_context& context) {
  evrard_run s;
  sph::configure(s, context);
  s.problem = evrard::problem_parameters().read(context.parameters());
  sph::require_equation_of_state(s.physics, flecsph::physics::eos_type::ideal_gas, s.program, "the Evrard collapse");
  if (!s.physics.gravity.enabled) throw runtime::parameter_error("evrard: the Evrard collapse needs gravity = true");
  s.gravitational_constant = s.physics.gravity.constant;
  auto m = sph::make_app_control_model<evrard_run>(
    {[](evrard_run& state) { evrard::check_problem(state.problem, state.physics, state.gravitational_constant); },
     [](evrard_run& state) { evrard::create_sphere(state, state.problem, state.gravitational_constant); }});
  m.action("analyze", "energy_check", track_energy).after("statistics");
  m.action("finalize", "report", report);
  return context.execute(m, s, [&context](const evrard_run& state) { return check(state, context.checks()); });
}
}  // namespace

int main(int argc, char** argv) {
  sph::app_definition definition;
  definition.program = "evrard";
  definition.summary =
    "The Evrard collapse with SPH and self-gravity: H5Part output, energies K, U, W, E per step "
    "and their conservation.";
  definition.declare_parameters = [](runtime::parameter_schema& schema) {
    evrard::problem_parameters().declare(schema);
  };
  // Without a parameter file: the problem of apps/evrard/evrard.par (validation.defaults.evrard).
  definition.physics_defaults.eos.ideal.gamma = 5.0 / 3.0;
  definition.physics_defaults.conductivity = 0;
  definition.physics_defaults.gravity.enabled = true;
  definition.run_defaults.end_time = 3;
  definition.run_defaults.progress_every = 100;
  definition.run_defaults.diagnostics_every = 100;
  definition.file_defaults.output_file = "evrard.h5part";
  definition.file_defaults.output_every = 0.1;
  definition.file_defaults.checkpoint_file = "evrard.checkpoint.h5part";
  definition.checks = {{"check-energy", {"TOL"}, "exit with status 1 if |E - E0| / |E0| exceeds TOL at any step"}};
  definition.run = [](const app::run_context& context) { return run(context); };
  return sph::app_main(argc, argv, definition);
}
