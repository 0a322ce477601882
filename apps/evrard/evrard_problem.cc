// The Evrard problem's parameter keys, the checks of what they imply and the analytic initial
// energies (evrard_problem.hh).
#include "evrard_problem.hh"

#include <cmath>

namespace evrard {

namespace {
flecsi_lite::runtime::parameter_block<problem> declare_problem() {
  flecsi_lite::runtime::parameter_block<problem> sphere;
  sphere.integer("particles", &problem::particles, "about this many particles in the sphere").at_least(100);
  sphere.real("sphere_radius", &problem::radius, "radius R of the sphere").greater_than(0);
  sphere.real("sphere_mass", &problem::mass, "mass M of the sphere").greater_than(0);
  sphere.real("thermal_energy", &problem::thermal_energy, "initial specific internal energy in units of G M / R")
    .greater_than(0);
  return sphere;
}
}  // namespace

const flecsi_lite::runtime::parameter_block<problem>& problem_parameters() {
  static const auto block = declare_problem();
  return block;
}

void check_problem(const problem& problem, const sph::physics_settings& physics, double gravitational_constant) {
  const std::string keys = "particles, sphere_radius";
  flecsi_lite::runtime::checked_particles("evrard", double(problem.particles), "particles");
  const double radius =
    flecsi_lite::runtime::checked_length("evrard", "sphere radius", problem.radius, "sphere_radius");
  const double spacing = flecsi_lite::runtime::checked_length(
    "evrard", "mean spacing at the surface", radius * std::cbrt(4.0 / double(problem.particles)), keys);
  flecsi_lite::runtime::checked_length("evrard", "smoothing length at the surface", physics.eta * spacing,
                                       "eta, " + keys);
  flecsi_lite::runtime::checked_positive("evrard", "particle mass", problem.mass / double(problem.particles),
                                         "sphere_mass, particles");
  flecsi_lite::runtime::checked_positive("evrard", "initial internal energy",
                                         problem.thermal_energy * gravitational_constant * problem.mass / radius,
                                         "thermal_energy, gravitational_constant, sphere_mass, sphere_radius");
}

initial_energies analytic_energies(const problem& problem, double gravitational_constant) {
  const double g = gravitational_constant;
  return {-2.0 / 3.0 * g * problem.mass * problem.mass / problem.radius,
          problem.thermal_energy * g * problem.mass / problem.radius * problem.mass};
}

}  // namespace evrard
