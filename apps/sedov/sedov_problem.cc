// The Sedov blast's parameter keys, each declared once next to its member (sedov_problem.hh).
#include "sedov_problem.hh"

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
} // namespace

const flecsi_lite::runtime::parameter_block<problem>& problem_parameters() {
  static const auto block = declare_problem();
  return block;
}

} // namespace sedov
