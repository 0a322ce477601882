// The n = 1 polytrope, its lattice star and the binary of two relaxed stars (bns_problem.hh).
#include "bns_problem.hh"

#include "flecsi_lite/io.hh"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <sstream>
#include <vector>

namespace bns {
namespace {
const double pi = std::acos(-1.0);

flecsi_lite::runtime::parameter_block<problem> declare_problem() {
  flecsi_lite::runtime::parameter_block<problem> keys;
  keys.choice("setup", &problem::kind, setup_names(), "a single star, or a binary of two relaxed stars");
  keys.integer("particles", &problem::particles, "about this many particles in the lattice star (setup = star)")
    .at_least(100);
  keys.real("star_mass", &problem::mass, "mass M of the (first) star").greater_than(0);
  keys.real("companion_mass", &problem::companion_mass, "mass of the second star (setup = binary)").greater_than(0);
  keys.real("star_radius", &problem::radius, "radius R of the stars (n = 1: K = 2 G R^2 / pi)").greater_than(0);
  keys.file("star_file", &problem::star_file, "setup = binary: H5Part file of a relaxed single star (last step)");
  keys.real("separation", &problem::separation, "setup = binary: distance a of the stars' centres").greater_than(0);
  keys.boolean("stable_orbit", &problem::stable_orbit,
               "setup = binary: require both stars inside their Roche lobes (Eggleton 1983)");
  keys.choice("orbit_omega", &problem::orbit_omega, omega_rule_names(),
              "setup = binary: Omega of the corotating frame and the release (kepler, or forces: balancing the "
              "stars' mean accelerations)");
  keys
    .real("relaxation_time", &problem::relaxation_time,
          "longest damped relaxation, in units of t_dyn = sqrt(R^3 / (G M)) (0: none)")
    .at_least(0);
  keys.real("relaxation_min_time", &problem::relaxation_min_time, "shortest relaxation, in units of t_dyn").at_least(0);
  keys.real("relaxation_tolerance", &problem::relaxation_tolerance, "the relaxation ends once K / |W| is below this")
    .greater_than(0);
  keys.real("damping_time", &problem::damping_time, "relaxation damping a -= v / (damping_time t_dyn)").greater_than(0);
  keys.real("observer_distance", &problem::observer_distance, "distance d of the strain's observer (z axis)")
    .greater_than(0);
  keys.real("speed_of_light", &problem::speed_of_light, "c of the strain and the radiation reaction, in code units")
    .greater_than(0);
  keys.boolean("radiation_reaction", &problem::radiation_reaction,
               "setup = binary: the 2.5PN point-mass radiation reaction on the stars after the release, until "
               "contact (radiation_reaction_cutoff)");
  keys
    .real("radiation_reaction_cutoff", &problem::radiation_reaction_cutoff,
          "the radiation reaction stops for good once the separation falls below this many star radii")
    .greater_than(0);
  keys.file("star_cache", &problem::star_cache,
            "setup = binary: folder of relaxed stars keyed by the keys that make them (instead of star_file): "
            "reused when one exists, else relaxed first and kept there");
  keys
    .real("star_relaxation_time", &problem::star_relaxation_time,
          "star_cache: longest relaxation of a star made for the cache, in units of t_dyn")
    .greater_than(0);
  keys
    .real("star_relaxation_min_time", &problem::star_relaxation_min_time,
          "star_cache: shortest relaxation of a star made for the cache, in units of t_dyn")
    .at_least(0);
  keys
    .real("star_damping_time", &problem::star_damping_time,
          "star_cache: damping time of a star made for the cache, in units of t_dyn")
    .greater_than(0);
  keys.boolean("physical_constants", &problem::physical_constants,
               "G and c from unit_mass_in_cgs, unit_length_in_cgs, unit_time_in_cgs and their CGS values (then "
               "gravitational_constant and speed_of_light must not be set)");
  return keys;
}

/// sin(x) / x, 1 at x = 0.
double sinc(double x) { return std::fabs(x) < 1e-8 ? 1 - x * x / 6 : std::sin(x) / x; }
}  // namespace

const flecsi_lite::runtime::name_table<setup>& setup_names() {
  static const flecsi_lite::runtime::name_table<setup> table{"setup",
                                                             {{"star", setup::star}, {"binary", setup::binary}}};
  return table;
}

const flecsi_lite::runtime::name_table<omega_rule>& omega_rule_names() {
  static const flecsi_lite::runtime::name_table<omega_rule> table{
    "orbit_omega", {{"kepler", omega_rule::kepler}, {"forces", omega_rule::forces}}};
  return table;
}

const flecsi_lite::runtime::parameter_block<problem>& problem_parameters() {
  static const auto block = declare_problem();
  return block;
}

double central_density(double mass, double radius) { return pi * mass / (4 * radius * radius * radius); }

double lane_emden_density(double r, double mass, double radius) {
  if (r >= radius) return 0;
  return central_density(mass, radius) * sinc(pi * r / radius);
}

double enclosed_fraction(double r, double radius) {
  if (r >= radius) return 1;
  const double x = pi * r / radius;
  return (std::sin(x) - x * std::cos(x)) / pi;
}

double radius_of_fraction(double fraction, double radius) {
  if (fraction >= 1) return radius;
  double lo = 0, hi = radius;  // enclosed_fraction rises from 0 to 1
  for (int iteration = 0; iteration < 200 && hi - lo > 1e-16 * radius; ++iteration) {
    const double mid = 0.5 * (lo + hi);
    (enclosed_fraction(mid, radius) < fraction ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

double polytropic_constant(double radius, double gravitational_constant) {
  return 2 * gravitational_constant * radius * radius / pi;
}

double dynamical_time(double mass, double radius, double gravitational_constant) {
  return std::sqrt(radius * radius * radius / (gravitational_constant * mass));
}

double roche_lobe_fraction(double mass, double companion) {
  const double q = mass / companion, q3 = std::cbrt(q), q23 = q3 * q3;
  return 0.49 * q23 / (0.6 * q23 + std::log(1 + q3));
}

code_constants physical_constants_in_code_units(double mass_in_cgs, double length_in_cgs, double time_in_cgs) {
  const double G_cgs = 6.67430e-8, c_cgs = 2.99792458e10;
  return {G_cgs * mass_in_cgs * time_in_cgs * time_in_cgs / (length_in_cgs * length_in_cgs * length_in_cgs),
          c_cgs * time_in_cgs / length_in_cgs};
}

double kepler_omega(const problem& problem, double gravitational_constant) {
  const double a = problem.separation;
  return std::sqrt(gravitational_constant * (problem.mass + problem.companion_mass) / (a * a * a));
}

void check_problem(const problem& problem, const sph::physics_settings& physics, bool polytropic_constant_set) {
  using flecsi_lite::runtime::parameter_error;
  std::ostringstream m;
  m.precision(6);
  if (!physics.gravity.enabled) throw parameter_error("bns: the stars need self-gravity: set gravity = true");
  if (polytropic_constant_set)
    throw parameter_error(
      "bns: polytropic_constant follows from star_radius and gravitational_constant "
      "(n = 1: K = 2 G R^2 / pi); do not set it");
  if (physics.eos.type == flecsph::physics::eos_type::polytropic && physics.eos.polytrope.polytropic_exponent != 2) {
    m << "bns: polytropic_exponent = " << physics.eos.polytrope.polytropic_exponent
      << ": the stars are n = 1 polytropes, Gamma = 2";
    throw parameter_error(m.str());
  }
  if (physics.eos.type == flecsph::physics::eos_type::ideal_gas && physics.eos.ideal.gamma != 2) {
    m << "bns: gamma = " << physics.eos.ideal.gamma
      << " with eos = ideal_gas: the n = 1 stars are in equilibrium with u = K rho at gamma = 2 only";
    throw parameter_error(m.str());
  }
  if (physics.eos.type == flecsph::physics::eos_type::isothermal)
    throw parameter_error("bns: eos = isothermal: the stars need eos = polytropic or ideal_gas (gamma 2)");
  flecsi_lite::runtime::checked_length("bns", "star radius", problem.radius, "star_radius");
  flecsi_lite::runtime::checked_positive("bns", "dynamical time",
                                         dynamical_time(problem.mass, problem.radius, physics.gravity.constant),
                                         "star_mass, star_radius, gravitational_constant");
  if (problem.kind == setup::star) {
    flecsi_lite::runtime::checked_particles("bns", double(problem.particles), "particles");
    flecsi_lite::runtime::checked_length(
      "bns", "mean spacing", problem.radius * std::cbrt(4.0 / double(problem.particles)), "particles, star_radius");
    return;
  }
  if (problem.star_file.empty() && problem.star_cache.empty())
    throw parameter_error(
      "bns: setup = binary needs star_file, the H5Part file of a relaxed single star, or star_cache, a folder of "
      "them");
  if (!problem.star_file.empty() && !problem.star_cache.empty())
    throw parameter_error("bns: star_file = '" + problem.star_file + "' and star_cache = '" + problem.star_cache +
                          "' both name the star: set one of them");
  const double a = problem.separation, R = problem.radius;
  if (a <= 2 * R) {
    m << "bns: separation = " << a << " is at most the sum of the stars' radii 2 star_radius = " << 2 * R
      << ": the stars overlap at the start (keys separation, star_radius)";
    throw parameter_error(m.str());
  }
  if (problem.stable_orbit) {
    const double lobe = std::min(roche_lobe_fraction(problem.mass, problem.companion_mass),
                                 roche_lobe_fraction(problem.companion_mass, problem.mass));
    if (R >= lobe * a) {
      m << "bns: separation = " << a << " with star_radius = " << R << ": a star fills its Roche lobe (Eggleton "
        << "1983: r_L = " << lobe << " a = " << lobe * a << " for the mass ratio of star_mass, companion_mass), so "
        << "the orbit is not stable; the separation must exceed R / " << lobe << " = " << R / lobe
        << ", or set stable_orbit = false (a merger)";
      throw parameter_error(m.str());
    }
  }
}

void create_star(sph::simulation<3>& s, const problem& problem) {
  const auto sites = spheres::ball_lattice(problem.particles);
  const auto block =
    flecsi_lite::io::block_slice(sites.size(), flecsi_lite::runtime::rank(), flecsi_lite::runtime::size());
  sph::create_particles(s, block.count);
  const double mass = problem.mass / double(sites.size()), R = problem.radius;
  const double K = polytropic_constant(R, s.physics.gravity.constant);
  const double floor = 1e-2 * central_density(problem.mass, R);  // h of the outermost sites: the density pass finds it
  sph::initial_fields(s, [&](std::size_t i, sph::initial_particle<3>& p) {
    const std::uint64_t index = block.offset + i;
    const auto& site = sites[index];
    const double r0 = spheres::radius(site);
    // The uniform ball holds r0^3 of its mass inside r0: that fraction of the polytrope's.
    const double r = r0 > 1 ? R * r0 : radius_of_fraction(r0 * r0 * r0, R);
    for (int k = 0; k < 3; ++k) p.x[k] = r0 > 0 ? site[static_cast<std::size_t>(k)] * r / r0 : 0.0;
    p.rho = std::max(lane_emden_density(r, problem.mass, R), floor);
    p.id = index;
    p.m = mass;
    p.h = s.physics.eta * std::cbrt(mass / p.rho);
    p.u = K * p.rho;  // K rho^(Gamma - 1) / (Gamma - 1) at Gamma = 2
    p.kind = sph::particle_kind::fluid;
  });
}

std::uint64_t star_file_particles(const problem& problem) {
  const flecsi_lite::io::h5part_reader in(problem.star_file);
  return in.particle_count(in.last_step());
}

void create_binary(sph::simulation<3>& s, const problem& problem) {
  const flecsi_lite::io::h5part_reader in(problem.star_file);
  const auto step = in.last_step();
  const std::uint64_t n = in.particle_count(step);
  if (n == 0) throw std::invalid_argument("bns: star_file '" + problem.star_file + "' holds no particles");
  const double file_mass = in.root_attribute_as<double>("star_mass");
  const double file_radius = in.root_attribute_as<double>("star_radius");
  const double file_G = in.root_attribute_as<double>("gravitational_constant");
  // Every rank reads the whole star (a few thousand particles), in id order.
  const flecsi_lite::io::slice all{0, n};
  const auto read = [&](const char* name) { return in.read<double>(step, name, all); };
  const auto x = read("x"), y = read("y"), z = read("z"), m = read("m"), h = read("h"), u = read("u"),
             rho = read("rho");
  const auto id = in.read<std::uint64_t>(step, "id", all);
  std::vector<std::size_t> order(n);
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return id[a] < id[b]; });
  double centre[3] = {0, 0, 0}, total = 0;
  for (const std::size_t a : order) {
    total += m[a];
    centre[0] += m[a] * x[a], centre[1] += m[a] * y[a], centre[2] += m[a] * z[a];
  }
  for (double& c : centre) c /= total;
  const double length = problem.radius / file_radius;
  const double M = problem.mass + problem.companion_mass;
  const double offsets[2] = {-problem.separation * problem.companion_mass / M, problem.separation * problem.mass / M};
  const double masses[2] = {problem.mass / file_mass, problem.companion_mass / file_mass};
  const auto block = flecsi_lite::io::block_slice(2 * n, flecsi_lite::runtime::rank(), flecsi_lite::runtime::size());
  sph::create_particles(s, block.count);
  sph::initial_fields(s, [&](std::size_t i, sph::initial_particle<3>& p) {
    const std::uint64_t index = block.offset + i;
    const int star = index >= n ? 1 : 0;
    const std::size_t a = order[index - std::uint64_t(star) * n];
    // Homologous: x ~ R, m ~ M, rho ~ M / R^3, u ~ G M / R (u = K rho with K = 2 G R^2 / pi).
    const double q = masses[star];
    p.x = {offsets[star] + length * (x[a] - centre[0]), length * (y[a] - centre[1]), length * (z[a] - centre[2])};
    p.m = q * m[a];
    p.h = length * h[a];
    p.rho = q * rho[a] / (length * length * length);
    p.u = q * u[a] / length * (s.physics.gravity.constant / file_G);
    p.id = index;
    p.kind = sph::particle_kind::fluid;
  });
}

}  // namespace bns
