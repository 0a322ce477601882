// glass: relaxes equal-mass particles at random positions in the periodic unit box (2D or 3D) to a
// glass with damped SPH pressure forces at a uniform temperature (glass_problem.hh), until the
// relative density scatter std(rho) / mean(rho) stops falling. The last step of the H5Part output
// is the glass, which sedov and noh read with `initial_lattice = glass` (glass_tiling.hh); by
// default it is written under the cache name that they look for. Its quality (density scatter,
// structure factor against a lattice's) is measured by tests/validation/check_glass.py.
//
//   glass apps/glass/glass_2d.par [--set particles_per_side=64] [--check-scatter 0.01]
#include "glass_problem.hh"
#include "glass_tiling.hh"

#include "specialization/sph.hh"

#include "flecsi_lite/app.hh"
#include "flecsi_lite/runtime.hh"
#include "flecsi_lite/util.hh"

#include <cmath>
#include <iomanip>
#include <sstream>
#include <string>

namespace {
using namespace flecsi_lite;
namespace sph = flecsph::sph;

template<int D>
struct glass_run : sph::app_state<D> {
  glass::problem problem;
  double first_scatter = -1, scatter = 0;
  double reference_scatter = 0,
         next_check = 0;  ///< the scatter at the last convergence check, and the next check's time
  bool converged = false;
};

/// The exact sums of rho and rho^2 over the fluid particles (so the scatter is the same on any
/// number of ranks).
struct density_sums {
  util::exact_sum sum, squares, count;
  density_sums& operator+=(const density_sums& other) {
    sum += other.sum;
    squares += other.squares;
    count += other.count;
    return *this;
  }
};
struct density_reduction {
  static density_sums combine(density_sums a, const density_sums& b) { return a += b; }
};

density_sums sum_density(sph::ro<sph::particle_kind> kind, sph::ro<double> rho) {
  density_sums sums;
  for (std::size_t a = 0; a < rho.size(); ++a) {
    if (kind(a) != sph::particle_kind::fluid) continue;
    sums.sum += rho(a);
    sums.squares += rho(a) * rho(a);
    sums.count += 1.0;
  }
  return sums;
}

/// std(rho) / mean(rho) over all particles. Collective.
template<int D>
double density_scatter(glass_run<D>& s) {
  using f = sph::fields<D>;
  auto& p = *s.particles;
  const auto sums = reduce<sum_density, density_reduction>(f::kind(p), f::density(p)).get();
  const double n = sums.count.value(), mean = sums.sum.value() / n;
  const double variance = std::max(0.0, sums.squares.value() / n - mean * mean);
  return std::sqrt(variance) / mean;
}

/// a -= v / tau, and du/dt = 0: the gas keeps its temperature, so the only minimum of the energy
/// it relaxes in is uniform density.
template<int D>
void damp(double inverse_damping, sph::ro<sph::vector<D>> v, sph::rw<sph::vector<D>> a, sph::wo<double> du_dt) {
  forall(
    v.size(),
    [&](std::size_t p) {
      for (int k = 0; k < D; ++k) a(p)[k] -= v(p)[k] * inverse_damping;
      du_dt(p) = 0;
    },
    "glass::damp");
}

template<int D>
void damping(glass_run<D>& s) {
  using f = sph::fields<D>;
  auto& p = *s.particles;
  execute<damp<D>>(1 / s.problem.damping_time, f::velocity(p), f::acceleration(p), f::internal_energy_rate(p));
}

/// After each step: the scatter; every convergence_interval, the run ends once it fell by less
/// than convergence_tolerance since the last check.
template<int D>
void convergence(glass_run<D>& s) {
  s.scatter = density_scatter(s);
  if (s.first_scatter < 0) {
    s.first_scatter = s.reference_scatter = s.scatter;
    s.next_check = s.time + s.problem.convergence_interval;
    return;
  }
  if (s.time < s.next_check || s.problem.convergence_tolerance <= 0) return;
  const double fall = (s.reference_scatter - s.scatter) / s.reference_scatter;
  log::info() << std::setprecision(5) << "glass: t = " << s.time << ": density scatter " << s.scatter << " (fell by "
              << fall << " since t = " << s.next_check - s.problem.convergence_interval << ")";
  if (fall < s.problem.convergence_tolerance) {
    s.converged = true;
    s.finished = true;
  }
  s.reference_scatter = s.scatter;
  s.next_check = s.time + s.problem.convergence_interval;
}

template<int D>
void report(glass_run<D>& s) {
  s.scatter = density_scatter(s);
  std::ostringstream line;
  line << std::setprecision(5) << "glass: " << s.particles->global_size() << " particles at t = " << s.time << " (step "
       << s.step << "): relative density scatter " << s.scatter << " (random start " << s.first_scatter << "); "
       << (s.converged ? "converged (the scatter stopped falling)" : "stopped at end_time before converging")
       << "; the glass is the last step of '" << s.files.output_file << "'";
  log::info() << line.str();
}

/// --check-scatter S: exit status 1 unless the final density scatter is at most S.
template<int D>
int check(const glass_run<D>& s, const app::check_values& checks) {
  if (!checks.has("check-scatter")) return 0;
  const double bound = checks.bounds("check-scatter")[0];
  if (s.scatter <= bound) return 0;
  log::error() << "glass: check failed: density scatter " << s.scatter << " > " << bound;
  return 1;
}

template<int D>
int run(const app::run_context& context) {
  glass_run<D> s;
  sph::configure(s, context);
  s.problem = glass::problem_parameters().read(context.parameters());
  sph::require_equation_of_state(s.physics, flecsph::physics::eos_type::ideal_gas, s.program,
                                 "the isothermal relaxation");
  if (s.physics.individual_time_steps())
    throw runtime::parameter_error(
      "glass: time_steps = individual: the relaxation damps every particle's velocity "
      "in every step, which individual steps do not take; use time_steps = global");
  // The convergence test's history (the scatter at the last check) is not in the checkpoints, so a
  // resumed relaxation would stop at another step than the uninterrupted one.
  if (!s.files.restart_file.empty())
    throw runtime::parameter_error("glass: restart_file = '" + s.files.restart_file +
                                   "': a glass relaxation cannot be resumed (its convergence history is not in the "
                                   "checkpoint); rerun it, it takes seconds to minutes");
  // The default output is the cache file sedov and noh look for (glass_tiling.hh).
  if (context.parameters().origin("output_file") == "default")
    s.files.output_file = glass::cache_name(
      D, s.problem.per_side, std::string(flecsph::physics::kernel_name(s.physics.kernel)), s.physics.eta);
  s.description = glass::glass_attributes(s.problem.per_side, s.physics);
  s.description["seed"] = std::int64_t{s.problem.seed};
  s.extra_statistics_columns = {{"density_scatter", "std(rho) / mean(rho) over all particles", "1"}};
  s.extra_statistics = [&s] { return std::vector<double>{density_scatter(s)}; };
  auto m = sph::make_app_control_model<glass_run<D>>(
    {[](glass_run<D>& state) { glass::set_periodic_box(state, state.problem); },
     [](glass_run<D>& state) { glass::create_random(state, state.problem); }});
  m.action("force_evaluation", "damping", damping<D>).after("forces");
  m.action("initialize", "first_scatter", convergence<D>).after("diagnostics");
  m.action("analyze", "convergence", convergence<D>).after("run_limits");
  m.action("finalize", "report", report<D>);
  return context.execute(m, s, [&context](const glass_run<D>& state) { return check(state, context.checks()); });
}
}  // namespace

int main(int argc, char** argv) {
  sph::app_definition definition;
  definition.program = "glass";
  definition.summary = "Relaxes random particles in the periodic unit box to a glass (2D, 3D): H5Part output.";
  definition.declare_parameters = [](runtime::parameter_schema& schema) {
    glass::problem_parameters().declare(schema);
  };
  definition.physics_defaults.conductivity = 0;
  definition.run_defaults.end_time = 10;
  definition.run_defaults.progress_every = 100;
  definition.run_defaults.diagnostics_every = 100;
  definition.file_defaults.output_file = "glass.h5part";
  definition.file_defaults.output_every = 0;
  definition.file_defaults.checkpoint_file = "glass.checkpoint.h5part";
  definition.checks = {{"check-scatter", {"S"}, "exit with status 1 unless the final density scatter is at most S"}};
  definition.run = [](const app::run_context& context) {
    return context.parameters().get<int>("dimension") == 2 ? run<2>(context) : run<3>(context);
  };
  return sph::app_main(argc, argv, definition);
}
