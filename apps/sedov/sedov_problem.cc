// The Sedov blast's parameters (sedov_problem.hh).
#include "sedov_problem.hh"

namespace sedov {

void declare_parameters(flecsi_lite::runtime::parameter_schema& schema) {
  const problem d;
  schema.integer("dimension", "2 (cylindrical blast) or 3 (spherical)").default_value(d.dimension).range(2, 3);
  schema.integer("particles_per_side", "lattice particles per side of the box").default_value(d.per_side).at_least(4);
  schema.real("box_side", "side of the periodic box centred on the blast").default_value(d.side).greater_than(0);
  schema.real("blast_energy", "energy deposited at the centre").default_value(d.energy).greater_than(0);
  schema.real("rho0", "density of the medium").default_value(d.rho0).greater_than(0);
  schema.real("background_pressure", "pressure of the (nearly cold) medium")
    .default_value(d.background_pressure)
    .greater_than(0);
}

problem problem_from(const flecsi_lite::runtime::parameters& p) {
  problem result;
  result.dimension = p.get<int>("dimension");
  result.per_side = p.get<std::int64_t>("particles_per_side");
  result.side = p.get<double>("box_side");
  result.energy = p.get<double>("blast_energy");
  result.rho0 = p.get<double>("rho0");
  result.background_pressure = p.get<double>("background_pressure");
  return result;
}

} // namespace sedov
