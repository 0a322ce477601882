// The cold collapse's parameter keys, the checks of what they imply and the free-fall solution
// (cold_collapse_problem.hh).
#include "cold_collapse_problem.hh"

#include <cmath>

namespace cold_collapse {

namespace {
flecsi_lite::runtime::parameter_block<problem> declare_problem() {
  flecsi_lite::runtime::parameter_block<problem> sphere;
  sphere.integer("particles", &problem::particles, "about this many particles in the sphere").at_least(100);
  sphere.real("sphere_radius", &problem::radius, "radius R of the sphere").greater_than(0);
  sphere.real("sphere_mass", &problem::mass, "mass M of the sphere").greater_than(0);
  sphere.real("thermal_energy", &problem::thermal_energy, "specific internal energy in units of G M / R (tiny: cold)")
    .greater_than(0);
  sphere
    .real("radius_mass_fraction", &problem::mass_fraction,
          "the radius compared with free fall holds this fraction of the mass")
    .greater_than(0)
    .at_most(1);
  sphere
    .real("compare_until", &problem::compare_until,
          "compare the radius with free fall up to this fraction of the free-fall time")
    .greater_than(0)
    .at_most(1);
  return sphere;
}
}  // namespace

const flecsi_lite::runtime::parameter_block<problem>& problem_parameters() {
  static const auto block = declare_problem();
  return block;
}

void check_problem(const problem& problem, const sph::physics_settings& physics, double gravitational_constant) {
  const std::string keys = "particles, sphere_radius";
  flecsi_lite::runtime::checked_particles("cold_collapse", double(problem.particles), "particles");
  const double radius =
    flecsi_lite::runtime::checked_length("cold_collapse", "sphere radius", problem.radius, "sphere_radius");
  const double spacing = flecsi_lite::runtime::checked_length(
    "cold_collapse", "mean spacing", radius * std::cbrt(4.0 / double(problem.particles)), keys);
  flecsi_lite::runtime::checked_length("cold_collapse", "smoothing length", physics.eta * spacing, "eta, " + keys);
  flecsi_lite::runtime::checked_positive("cold_collapse", "particle mass", problem.mass / double(problem.particles),
                                         "sphere_mass, particles");
  flecsi_lite::runtime::checked_positive("cold_collapse", "internal energy",
                                         problem.thermal_energy * gravitational_constant * problem.mass / radius,
                                         "thermal_energy, gravitational_constant, sphere_mass, sphere_radius");
  flecsi_lite::runtime::checked_positive("cold_collapse", "free-fall time",
                                         free_fall_time(problem, gravitational_constant),
                                         "sphere_radius, sphere_mass, gravitational_constant");
}

double free_fall_time(const problem& problem, double gravitational_constant) {
  const double pi = std::acos(-1.0);
  return 0.5 * pi * std::sqrt(std::pow(problem.radius, 3) / (2.0 * gravitational_constant * problem.mass));
}

double free_fall_radius(double tau) {
  if (tau <= 0) return 1;
  if (tau >= 1) return 0;
  const double pi = std::acos(-1.0);
  const auto time_of = [pi](double x) { return 2.0 / pi * (std::acos(std::sqrt(x)) + std::sqrt(x * (1.0 - x))); };
  double lo = 0, hi = 1;  // time_of decreases from 1 at x = 0 to 0 at x = 1
  for (int iteration = 0; iteration < 200 && hi - lo > 1e-16; ++iteration) {
    const double mid = 0.5 * (lo + hi);
    (time_of(mid) > tau ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

}  // namespace cold_collapse
