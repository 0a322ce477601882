// The square test's keys, lattices and checks (square_problem.hh).
#include "square_problem.hh"

namespace square {

namespace {
flecsi_lite::runtime::parameter_block<problem> declare_problem() {
  flecsi_lite::runtime::parameter_block<problem> keys;
  keys.integer("particles_per_side", &problem::per_side, "ambient lattice particles per side of the unit box")
    .at_least(8);
  keys.real("square_density", &problem::square_density, "density of the square [1/4, 3/4]^2").greater_than(0);
  keys.real("ambient_density", &problem::ambient_density, "density around the square").greater_than(0);
  keys.real("pressure", &problem::pressure, "the common pressure").greater_than(0);
  return keys;
}
}  // namespace

const flecsi_lite::runtime::parameter_block<problem>& problem_parameters() {
  static const auto block = declare_problem();
  return block;
}

std::int64_t square_per_side(const problem& problem) {
  return std::llround(0.5 * double(problem.per_side) * std::sqrt(problem.square_density / problem.ambient_density));
}

void check_problem(const problem& problem, const sph::physics_settings& physics) {
  if (problem.per_side % 4 != 0)
    throw flecsi_lite::runtime::parameter_error(
      "square: particles_per_side = " + std::to_string(problem.per_side) +
      " must be a multiple of 4 (the square's edges at 1/4 and 3/4 then fall between lattice sites)");
  const double inner = flecsi_lite::runtime::checked_count(
    "square", "square lattice particles per side",
    0.5 * double(problem.per_side) * std::sqrt(problem.square_density / problem.ambient_density),
    "particles_per_side, square_density, ambient_density");
  const double exact = 0.5 * double(problem.per_side) * std::sqrt(problem.square_density / problem.ambient_density);
  if (inner < 1 || std::fabs(inner - exact) > 1e-9 * exact)
    throw flecsi_lite::runtime::parameter_error(
      "square: equal masses need a whole number of square lattice particles per side, "
      "particles_per_side sqrt(square_density / ambient_density) / 2 = " +
      std::to_string(exact));
  flecsi_lite::runtime::checked_particles("square", double(problem.per_side) * double(problem.per_side) + inner * inner,
                                          "particles_per_side, square_density, ambient_density");
  const double spacing = 1.0 / double(problem.per_side);
  flecsi_lite::runtime::checked_length("square", "smoothing length",
                                       physics.eta * spacing * 0.5 / inner * double(problem.per_side),
                                       "eta, particles_per_side, square_density");
  for (const double rho : {problem.square_density, problem.ambient_density})
    flecsi_lite::runtime::checked_positive("square", "internal energy",
                                           physics.eos.ideal.internal_energy(rho, problem.pressure),
                                           "pressure, square_density, ambient_density, gamma");
}

std::vector<site> lattice_sites(const problem& problem) {
  std::vector<site> sites;
  const std::int64_t n = problem.per_side, inner = square_per_side(problem);
  const auto inside = [](double c) { return c > 0.25 && c < 0.75; };
  for (std::int64_t j = 0; j < n; ++j)
    for (std::int64_t i = 0; i < n; ++i) {
      const double x = (double(i) + 0.5) / double(n), y = (double(j) + 0.5) / double(n);
      if (!(inside(x) && inside(y))) sites.push_back({x, y, false});
    }
  for (std::int64_t j = 0; j < inner; ++j)
    for (std::int64_t i = 0; i < inner; ++i)
      sites.push_back(
        {0.25 + (double(i) + 0.5) * 0.5 / double(inner), 0.25 + (double(j) + 0.5) * 0.5 / double(inner), true});
  return sites;
}

}  // namespace square
