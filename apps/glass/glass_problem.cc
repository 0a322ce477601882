// The glass generator's parameter keys and the checks of what they imply (glass_problem.hh).
#include "glass_problem.hh"

namespace glass {

namespace {
flecsi_lite::runtime::parameter_block<problem> declare_problem() {
  flecsi_lite::runtime::parameter_block<problem> keys;
  keys.integer("dimension", &problem::dimension, "2 or 3").range(2, 3);
  keys.integer("particles_per_side", &problem::per_side, "N = particles_per_side^D particles in the unit box")
    .at_least(4);
  keys.integer("seed", &problem::seed, "seed of the random initial positions").at_least(0);
  keys.real("sound_speed", &problem::sound_speed, "sound speed of the isothermal gas").greater_than(0);
  keys.real("damping_time", &problem::damping_time, "velocity damping a -= v / damping_time").greater_than(0);
  keys
    .real("convergence_tolerance", &problem::convergence_tolerance,
          "stop when the density scatter fell by less than this fraction over convergence_interval (0: run to "
          "end_time)")
    .at_least(0)
    .at_most(1);
  keys
    .real("convergence_interval", &problem::convergence_interval,
          "time over which the fall of the density scatter is measured")
    .greater_than(0);
  return keys;
}
}  // namespace

const flecsi_lite::runtime::parameter_block<problem>& problem_parameters() {
  static const auto block = declare_problem();
  return block;
}

void check_problem(const problem& problem, const sph::physics_settings& physics, int dimension) {
  flecsi_lite::runtime::checked_particles("glass", std::pow(double(problem.per_side), dimension),
                                          "particles_per_side, dimension");
  const double spacing =
    flecsi_lite::runtime::checked_length("glass", "mean spacing", 1.0 / double(problem.per_side), "particles_per_side");
  flecsi_lite::runtime::checked_length("glass", "smoothing length", physics.eta * spacing, "eta, particles_per_side");
  flecsi_lite::runtime::checked_positive("glass", "internal energy", internal_energy(problem, physics),
                                         "sound_speed, gamma");
}

}  // namespace glass
