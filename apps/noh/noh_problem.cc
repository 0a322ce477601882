// The Noh implosion's parameter keys, each declared once next to its member, and the checks of the
// quantities they imply (noh_problem.hh).
#include "noh_problem.hh"

#include "cubic_lattice_checks.hh"

#include <cmath>

namespace noh {

namespace {
flecsi_lite::runtime::parameter_block<problem> declare_problem() {
  flecsi_lite::runtime::parameter_block<problem> implosion;
  implosion.integer("dimension", &problem::dimension, "2 (cylindrical implosion) or 3 (spherical)").range(2, 3);
  implosion.integer("particles_per_side", &problem::per_side, "lattice particles per side of the box").at_least(4);
  implosion.real("box_side", &problem::side, "side of the box [-L/2, L/2]^D the gas starts in").greater_than(0);
  implosion.real("rho0", &problem::rho0, "density of the inflowing gas").greater_than(0);
  implosion.real("inflow_speed", &problem::speed, "speed of the gas towards the centre").greater_than(0);
  implosion.real("pressure", &problem::pressure, "pressure of the (nearly cold) gas").greater_than(0);
  return implosion;
}
}  // namespace

const flecsi_lite::runtime::parameter_block<problem>& problem_parameters() {
  static const auto block = declare_problem();
  return block;
}

void check_problem(const problem& problem, const sph::physics_settings& physics, int dimension) {
  lattices::check_cubic_lattice("noh", {problem.per_side, problem.side, problem.rho0}, physics.eta, dimension);
  flecsi_lite::runtime::checked_positive("noh", "internal energy of the gas",
                                         physics.eos.ideal.internal_energy(problem.rho0, problem.pressure),
                                         "pressure, rho0, gamma");
}

}  // namespace noh
