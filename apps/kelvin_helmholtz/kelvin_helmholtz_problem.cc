// The Kelvin-Helmholtz problem's keys, its profile and its rows of equal-mass particles
// (kelvin_helmholtz_problem.hh).
#include "kelvin_helmholtz_problem.hh"

#include <algorithm>

namespace kelvin_helmholtz {

namespace {
flecsi_lite::runtime::parameter_block<problem> declare_problem() {
  flecsi_lite::runtime::parameter_block<problem> keys;
  keys.integer("particles_per_side", &problem::per_side, "particles per unit length where rho = rho1").at_least(8);
  keys.real("rho1", &problem::rho1, "density of the outer bands |y - 1/2| > 1/4").greater_than(0);
  keys.real("rho2", &problem::rho2, "density of the middle band").greater_than(0);
  keys.real("u1", &problem::u1, "x velocity of the outer bands");
  keys.real("u2", &problem::u2, "x velocity of the middle band");
  keys.real("smoothing", &problem::smoothing, "L of the exponential profiles (McNally et al. 2012)")
    .greater_than(0)
    .at_most(0.1);
  keys.real("pressure", &problem::pressure, "the uniform pressure").greater_than(0);
  keys.real("perturbation", &problem::perturbation, "amplitude A of v_y = A sin(4 pi x)");
  return keys;
}

/// The mass below y of the density profile (the exact integral of its four exponential pieces).
double mass_below(double y, const problem& p) {
  const double a = p.rho1, b = p.rho2, middle = (a - b) / 2, L = p.smoothing, tail = std::exp(-0.25 / L);
  const double quarter = a * 0.25 - middle * L * (1 - tail);
  const double half = quarter + b * 0.25 + middle * L * (1 - tail);
  const double three_quarters = half + b * 0.25 + middle * L * (1 - tail);
  if (y < 0.25) return a * y - middle * L * (std::exp((y - 0.25) / L) - tail);
  if (y < 0.5) return quarter + b * (y - 0.25) - middle * L * (std::exp((0.25 - y) / L) - 1);
  if (y < 0.75) return half + b * (y - 0.5) + middle * L * (std::exp((y - 0.75) / L) - tail);
  return three_quarters + a * (std::min(y, 1.0) - 0.75) + middle * L * (std::exp((0.75 - std::min(y, 1.0)) / L) - 1);
}

/// The y in [0, 1] below which the mass is `mass` (bisection: the mass grows with y).
double height_of_mass(double mass, const problem& p) {
  double low = 0, high = 1;
  for (int i = 0; i < 80; ++i) {
    const double middle = 0.5 * (low + high);
    (mass_below(middle, p) < mass ? low : high) = middle;
  }
  return 0.5 * (low + high);
}
}  // namespace

const flecsi_lite::runtime::parameter_block<problem>& problem_parameters() {
  static const auto block = declare_problem();
  return block;
}

double profile(double y, double outer, double inner, double smoothing) {
  const double middle = (outer - inner) / 2;
  if (y < 0.25) return outer - middle * std::exp((y - 0.25) / smoothing);
  if (y < 0.5) return inner + middle * std::exp((0.25 - y) / smoothing);
  if (y < 0.75) return inner + middle * std::exp((y - 0.75) / smoothing);
  return outer - middle * std::exp((0.75 - y) / smoothing);
}

double total_mass(const problem& problem) { return mass_below(1.0, problem); }

std::vector<row> particle_rows(const problem& problem) {
  // First the counts: at each row's start the spacing sqrt(m / rho) of the local density.
  const double trial_mass = problem.rho1 / double(problem.per_side * problem.per_side);
  const double total = total_mass(problem);
  std::vector<std::int64_t> counts;
  for (double mass = 0, y = 0; total - mass > 0.5 * trial_mass * double(problem.per_side);) {
    const double rho = profile(y, problem.rho1, problem.rho2, problem.smoothing);
    const auto count = std::max<std::int64_t>(1, std::llround(1 / std::sqrt(trial_mass / rho)));
    counts.push_back(count);
    mass += double(count) * trial_mass;
    y = height_of_mass(mass, problem);
  }
  // Then the mass per particle that fills the box exactly with those counts, and each row at the
  // middle (in mass) of its band.
  std::int64_t particles = 0;
  for (const auto count : counts) particles += count;
  const double mass = total / double(particles);
  std::vector<row> rows;
  double below = 0;
  for (std::size_t r = 0; r < counts.size(); ++r) {
    const double band = double(counts[r]) * mass;
    rows.push_back({height_of_mass(below + 0.5 * band, problem), counts[r], r % 2 ? 0.5 : 0.0});
    below += band;
  }
  return rows;
}

void check_problem(const problem& problem, const sph::physics_settings& physics) {
  const double densest = std::max(problem.rho1, problem.rho2), thinnest = std::min(problem.rho1, problem.rho2);
  flecsi_lite::runtime::checked_particles(
    "kelvin_helmholtz", double(problem.per_side) * double(problem.per_side) * densest / problem.rho1 * 1.5,
    "particles_per_side, rho1, rho2");
  flecsi_lite::runtime::checked_length("kelvin_helmholtz", "smoothing length",
                                       physics.eta / double(problem.per_side) * std::sqrt(problem.rho1 / densest),
                                       "eta, particles_per_side, rho1, rho2");
  flecsi_lite::runtime::checked_length("kelvin_helmholtz", "largest spacing",
                                       std::sqrt(problem.rho1 / thinnest) / double(problem.per_side),
                                       "particles_per_side, rho1, rho2");
  for (const double rho : {problem.rho1, problem.rho2})
    flecsi_lite::runtime::checked_positive("kelvin_helmholtz", "internal energy",
                                           physics.eos.ideal.internal_energy(rho, problem.pressure),
                                           "pressure, rho1, rho2, gamma");
}

}  // namespace kelvin_helmholtz
