// Parameter-file keys of the weakly compressible fluid (fluid_settings.hh), each declared once.
#include "specialization/fluid/fluid_settings.hh"

#include <sstream>

namespace flecsph::fluid {

namespace rt = flecsi_lite::runtime;

const rt::name_table<density_method>& density_method_names() {
  static const rt::name_table<density_method> table{
    "density method", {{"continuity", density_method::continuity}, {"summation", density_method::summation}}};
  return table;
}
const rt::name_table<viscosity_model>& viscosity_model_names() {
  static const rt::name_table<viscosity_model> table{
    "fluid viscosity", {{"laminar", viscosity_model::laminar}, {"artificial", viscosity_model::artificial}}};
  return table;
}
const rt::name_table<wall_condition>& wall_condition_names() {
  static const rt::name_table<wall_condition> table{
    "wall condition", {{"no_slip", wall_condition::no_slip}, {"free_slip", wall_condition::free_slip}}};
  return table;
}

namespace {
rt::parameter_block<fluid_settings> declare() {
  using rt::member;
  rt::parameter_block<fluid_settings> p;
  p.real("rho0", member(&fluid_settings::eos, &physics::tait::reference_density), "reference density of the Tait EOS")
    .greater_than(0)
    .at_most(1e50);
  p.real("c0", member(&fluid_settings::eos, &physics::tait::reference_sound_speed),
         "reference sound speed of the Tait EOS (about 10 times the largest flow speed)")
    .greater_than(0)
    .at_most(1e50);
  p.real("background_pressure", member(&fluid_settings::eos, &physics::tait::background_pressure),
         "background pressure of the Tait EOS (0 with a free surface)")
    .range(0, 1e50);
  p.choice("density_method", &fluid_settings::density, density_method_names(),
           "continuity (drho/dt) or summation (sum m W)");
  p.real("delta_sph", &fluid_settings::delta, "delta of the Molteni-Colagrossi density diffusion (0: off)").range(0, 1);
  p.choice("fluid_viscosity", &fluid_settings::viscosity, viscosity_model_names(),
           "laminar (Morris et al. 1997) or artificial (Monaghan 1992)");
  p.real("dynamic_viscosity", &fluid_settings::dynamic_viscosity, "mu = rho0 nu of the laminar viscosity")
    .range(0, 1e50);
  p.real("artificial_viscosity_alpha", &fluid_settings::artificial_alpha, "alpha of the artificial viscosity")
    .range(0, 10);
  p.real(
     "body_force_x", [](fluid_settings& s) -> double& { return s.body_force[0]; }, "body force (acceleration) x")
    .range(-1e50, 1e50);
  p.real(
     "body_force_y", [](fluid_settings& s) -> double& { return s.body_force[1]; }, "body force y (gravity: -9.81)")
    .range(-1e50, 1e50);
  p.real(
     "body_force_z", [](fluid_settings& s) -> double& { return s.body_force[2]; }, "body force z")
    .range(-1e50, 1e50);
  p.real("viscous_factor", &fluid_settings::viscous_factor, "dt <= factor h^2 / nu").greater_than(0).at_most(1);
  p.choice("wall_condition", &fluid_settings::walls, wall_condition_names(), "no_slip or free_slip walls");
  return p;
}
}  // namespace

const rt::parameter_block<fluid_settings>& fluid_parameters() {
  static const auto block = declare();
  return block;
}

void check_sound_speed(const std::string& program, const fluid_settings& settings) {
  const double c0 = settings.eos.reference_sound_speed, v = settings.expected_speed;
  std::ostringstream m;
  m.precision(4);
  m << program << ": c0 = " << c0 << " against the expected largest flow speed " << v;
  if (!(c0 > v)) throw rt::parameter_error(m.str() + ": c0 must exceed it (about 10 times, for 1% density variation)");
  if (c0 < 10 * v * (1 - 1e-9) && flecsi_lite::runtime::rank() == 0)
    flecsi_lite::log::warn() << m.str() << ": below 10 times it, density varies by more than ~1% (raise c0)";
}

}  // namespace flecsph::fluid
