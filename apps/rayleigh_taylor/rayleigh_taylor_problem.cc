// The Rayleigh-Taylor problem's keys, its profile, hydrostatic pressure and seed, and its rows of
// equal-mass particles with their walls (rayleigh_taylor_problem.hh).
#include "rayleigh_taylor_problem.hh"

#include "discrete_equilibrium.hh"

#include <algorithm>
#include <string>

namespace rayleigh_taylor {

namespace {
using flecsi_lite::runtime::checked_count;
using flecsi_lite::runtime::checked_length;
using flecsi_lite::runtime::checked_positive;

const std::string problem_keys = "particles_per_side, width, height, rho1, rho2, smoothing";

flecsi_lite::runtime::parameter_block<problem> declare_problem() {
  flecsi_lite::runtime::parameter_block<problem> keys;
  keys.integer("particles_per_side", &problem::per_side, "particles per unit length where rho = rho1").at_least(8);
  keys.real("width", &problem::width, "W: the period along x and the seed's wavelength").greater_than(0);
  keys.real("height", &problem::height, "H: the distance of the walls (interface at H / 2)").greater_than(0);
  keys.real("rho1", &problem::rho1, "density below the interface").greater_than(0);
  keys.real("rho2", &problem::rho2, "density above the interface").greater_than(0);
  keys.real("uniform_gravity", &problem::gravity, "g: the uniform acceleration is -g along y");
  keys.real("pressure", &problem::pressure, "P0: the pressure at the interface").greater_than(0);
  keys.real("smoothing", &problem::smoothing, "Delta of the logistic density profile").greater_than(0).at_most(0.1);
  keys.real("perturbation", &problem::perturbation, "delta: the largest v_y of the seed");
  keys
    .real("lattice_density", &problem::lattice_density,
          "density at which the rows are as far apart as their particles (0: rho1)")
    .at_least(0);
  keys.integer("wall_layers", &problem::wall_layers, "rows of fixed wall particles at each end (0: the kernel's reach)")
    .at_least(0);
  return keys;
}

/// log(1 + exp(z)) without overflow.
double softplus(double z) { return std::max(z, 0.0) + std::log1p(std::exp(-std::fabs(z))); }

/// The mass per unit width between y_i and y: int_{y_i}^{y} rho (exact for the logistic profile).
double column_mass(double y, const problem& p) {
  const double interface = 0.5 * p.height, d = p.smoothing;
  return p.rho1 * (y - interface) + (p.rho2 - p.rho1) * d * (softplus((y - interface) / d) - std::log(2.0));
}

/// The y in [0, H] below which the fluid's mass (per unit width) is `mass` (bisection).
double height_of_mass(double mass, const problem& p) {
  const double base = column_mass(0, p);
  double low = 0, high = p.height;
  for (int i = 0; i < 80; ++i) {
    const double middle = 0.5 * (low + high);
    (column_mass(middle, p) - base < mass ? low : high) = middle;
  }
  return 0.5 * (low + high);
}

/// The density at which the rows' lattice is isotropic.
double lattice_density(const problem& p) { return p.lattice_density > 0 ? p.lattice_density : p.rho1; }

/// Wall rows: a fluid particle next to a wall reaches 2 (1 + margin) h of walls, and those walls
/// need as deep a layer behind them for a complete density sum (as apps/sod).
std::int64_t wall_rows(const problem& p, const sph::physics_settings& physics) {
  if (p.wall_layers > 0) return p.wall_layers;
  return std::int64_t(std::ceil(2 * flecsph::physics::kernel_support * (1 + physics.search_margin) * physics.eta)) + 2;
}
}  // namespace

const flecsi_lite::runtime::parameter_block<problem>& problem_parameters() {
  static const auto block = declare_problem();
  return block;
}

double density(double y, const problem& p) {
  return p.rho1 + (p.rho2 - p.rho1) / (1 + std::exp(-(y - 0.5 * p.height) / p.smoothing));
}

double hydrostatic_pressure(double y, const problem& p) { return p.pressure - p.gravity * column_mass(y, p); }

sph::vector<2> seed_velocity(double x, double y, const problem& p) {
  const double pi = std::acos(-1.0), k = 2 * pi / p.width, e = y - 0.5 * p.height;
  const double r = std::sqrt(e * e + p.smoothing * p.smoothing), f = std::exp(-k * r);
  // v_x = -(delta / k) sin(k x) f'(e), f' = -k e / r f: div v = 0 exactly.
  return {p.perturbation * std::sin(k * x) * (e / r) * f, p.perturbation * std::cos(k * x) * f};
}

double particle_mass(const problem& p, const sph::physics_settings& physics) {
  std::int64_t fluid = 0;
  for (const row& r : particle_rows(p, physics))
    if (!r.wall) fluid += r.count;
  return p.width * (column_mass(p.height, p) - column_mass(0, p)) / double(fluid);
}

std::vector<row> particle_rows(const problem& p, const sph::physics_settings& physics) {
  // One count per row (discrete_equilibrium.hh), isotropic at lattice_density (rho1 by default:
  // rows isotropic at sqrt(rho1 rho2) left the bottom rows 1.4 spacings apart, which went unstable):
  // the rows' spacing follows the density (dy / dx = lattice_density / rho), each row at the middle
  // (in mass) of its band, alternate rows shifted by half a spacing.
  const double trial_mass = p.rho1 / double(p.per_side * p.per_side);
  const double total = column_mass(p.height, p) - column_mass(0, p);  // per unit width
  const auto count = std::max<std::int64_t>(1, std::llround(p.width / std::sqrt(trial_mass / lattice_density(p))));
  const auto fluid_rows = std::max<std::int64_t>(2, std::llround(p.width * total / (double(count) * trial_mass)));
  const double band = total / double(fluid_rows);
  std::vector<row> fluid;
  for (std::int64_t r = 0; r < fluid_rows; ++r)
    fluid.push_back({height_of_mass((double(r) + 0.5) * band, p), count, r % 2 ? 0.5 : 0.0, false});
  // The walls continue the end rows' spacing and alternation.
  const std::int64_t layers = wall_rows(p, physics);
  const double below = fluid[1].y - fluid[0].y, above = fluid[fluid.size() - 1].y - fluid[fluid.size() - 2].y;
  std::vector<row> rows;
  for (std::int64_t j = layers; j >= 1; --j)
    rows.push_back({fluid.front().y - double(j) * below, count, j % 2 ? 0.5 : 0.0, true});
  rows.insert(rows.end(), fluid.begin(), fluid.end());
  for (std::int64_t j = 1; j <= layers; ++j)
    rows.push_back({fluid.back().y + double(j) * above, count, (fluid_rows - 1 + j) % 2 ? 0.5 : 0.0, true});
  return rows;
}

void set_domain(sph::simulation<2>& s, const problem& p) {
  check_problem(p, s.physics);
  const auto rows = particle_rows(p, s.physics);
  const double margin = rows[1].y - rows[0].y + rows.back().y - rows[rows.size() - 2].y;
  flecsi_lite::topology::ntree::box<2> box;
  box.lo = {0.0, rows.front().y - margin};
  box.hi = {p.width, rows.back().y + margin};
  s.tree_settings.fixed_box = box;
  s.tree_settings.periodic = {true, false};
}

void create_particles(sph::simulation<2>& s, const problem& problem) {
  set_domain(s, problem);
  const auto rows = particle_rows(problem, s.physics);
  std::vector<std::int64_t> first(rows.size() + 1, 0);
  for (std::size_t r = 0; r < rows.size(); ++r) first[r + 1] = first[r] + rows[r].count;
  const auto total = static_cast<std::uint64_t>(first.back());
  const auto block = flecsi_lite::io::block_slice(total, flecsi_lite::runtime::rank(), flecsi_lite::runtime::size());
  sph::create_particles(s, block.count);
  const double mass = particle_mass(problem, s.physics);
  const auto states = discrete_equilibrium(rows, mass, problem, s.physics);
  std::size_t r = 0;
  sph::initial_fields(s, [&](std::size_t i, sph::initial_particle<2>& p) {
    const auto index = static_cast<std::int64_t>(block.offset + i);
    while (first[r + 1] <= index) ++r;  // particles come in order of index
    const row& here = rows[r];
    const double x = (double(index - first[r]) + 0.5 + here.shift) / double(here.count);
    p.id = static_cast<std::uint64_t>(index);
    p.x = {problem.width * (x - std::floor(x)), here.y};
    p.v = here.wall ? sph::vector<2>{0.0, 0.0} : seed_velocity(p.x[0], p.x[1], problem);
    p.m = mass;
    p.h = states[r].h;
    p.kind = here.wall ? sph::particle_kind::wall : sph::particle_kind::fluid;
    p.rho = states[r].rho;
    p.u = s.physics.eos.ideal.internal_energy(states[r].rho, states[r].pressure);
  });
}

void check_problem(const problem& p, const sph::physics_settings& physics) {
  const double densest = std::max(p.rho1, p.rho2), thinnest = std::min(p.rho1, p.rho2);
  checked_count("rayleigh_taylor", "particles",
                double(p.per_side) * double(p.per_side) * p.width * (p.height + 1) * densest / p.rho1 * 1.5,
                problem_keys);
  checked_length("rayleigh_taylor", "smoothing length", physics.eta / double(p.per_side) * std::sqrt(p.rho1 / densest),
                 "eta, " + problem_keys);
  checked_length("rayleigh_taylor", "largest spacing", std::sqrt(p.rho1 / thinnest) / double(p.per_side), problem_keys);
  checked_count("rayleigh_taylor", "particles per row",
                p.width * double(p.per_side) * std::sqrt(std::sqrt(p.rho1 * p.rho2) / p.rho1), problem_keys);
  checked_count("rayleigh_taylor", "wall layers", double(wall_rows(p, physics)), "wall_layers, eta, search_margin");
  // The lowest pressure is that of the top wall row: every internal energy is then positive.
  const auto rows = particle_rows(p, physics);
  for (const row* r : {&rows.front(), &rows.back()})
    checked_positive("rayleigh_taylor", "internal energy at y = " + std::to_string(r->y) + " (walls included)",
                     physics.eos.ideal.internal_energy(density(r->y, p), hydrostatic_pressure(r->y, p)),
                     "pressure, uniform_gravity, " + problem_keys + ", gamma");
}

}  // namespace rayleigh_taylor
