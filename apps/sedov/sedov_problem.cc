// The Sedov blast's parameter keys, each declared once next to its member, and the checks of the
// quantities they imply (sedov_problem.hh).
#include "sedov_problem.hh"

#include "cubic_lattice_checks.hh"

#include <cmath>

namespace sedov {

namespace {
flecsi_lite::runtime::parameter_block<problem> declare_problem() {
  flecsi_lite::runtime::parameter_block<problem> blast;
  blast.integer("dimension", &problem::dimension, "2 (cylindrical blast) or 3 (spherical)").range(2, 3);
  blast.integer("particles_per_side", &problem::per_side, "lattice particles per side of the box").at_least(4);
  blast.real("box_side", &problem::side, "side of the periodic box centred on the blast").greater_than(0);
  blast.real("blast_energy", &problem::energy, "energy deposited at the centre").greater_than(0);
  blast.real("rho0", &problem::rho0, "density of the medium").greater_than(0);
  blast.real("background_pressure", &problem::background_pressure, "pressure of the (nearly cold) medium")
    .greater_than(0);
  return blast;
}
}  // namespace

const flecsi_lite::runtime::parameter_block<problem>& problem_parameters() {
  static const auto block = declare_problem();
  return block;
}

void check_problem(const problem& problem, const sph::physics_settings& physics, int dimension) {
  lattices::check_cubic_lattice("sedov", {problem.per_side, problem.side, problem.rho0}, physics.eta, dimension);
  flecsi_lite::runtime::checked_positive("sedov", "mass of the box", problem.rho0 * std::pow(problem.side, dimension),
                                         "rho0, box_side");
  flecsi_lite::runtime::checked_positive("sedov", "specific energy of the blast",
                                         problem.energy / (problem.rho0 * std::pow(problem.side, dimension)),
                                         "blast_energy, rho0, box_side");
  flecsi_lite::runtime::checked_positive("sedov", "internal energy of the medium",
                                         physics.eos.ideal.internal_energy(problem.rho0, problem.background_pressure),
                                         "background_pressure, rho0, gamma");
}

}  // namespace sedov
