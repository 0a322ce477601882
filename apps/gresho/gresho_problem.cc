// The Gresho vortex's parameter keys and the checks of what they imply (gresho_problem.hh).
#include "gresho_problem.hh"

namespace gresho {

namespace {
flecsi_lite::runtime::parameter_block<problem> declare_problem() {
  flecsi_lite::runtime::parameter_block<problem> vortex;
  vortex.integer("particles_per_side", &problem::per_side, "lattice particles per side of the unit box").at_least(8);
  return vortex;
}
}  // namespace

const flecsi_lite::runtime::parameter_block<problem>& problem_parameters() {
  static const auto block = declare_problem();
  return block;
}

void check_problem(const problem& problem, const sph::physics_settings& physics) {
  flecsi_lite::runtime::checked_particles("gresho", double(problem.per_side) * double(problem.per_side),
                                          "particles_per_side");
  const double spacing = flecsi_lite::runtime::checked_length("gresho", "lattice spacing",
                                                              1.0 / double(problem.per_side), "particles_per_side");
  flecsi_lite::runtime::checked_length("gresho", "smoothing length", physics.eta * spacing, "eta, particles_per_side");
}

}  // namespace gresho
