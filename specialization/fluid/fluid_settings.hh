// The settings of weakly compressible SPH for liquids (Monaghan 1994; Adami, Hu & Adams 2012):
// the Tait EOS, density by continuity or summation, delta-SPH diffusion, laminar or artificial
// viscosity, the body force, the viscous time-step factor and the wall condition, with their keys.
#pragma once

#include "specialization/physics/tait.hh"

#include "flecsi_lite/runtime.hh"

#include <array>
#include <string>

namespace flecsph::fluid {

/// CONTINUITY integrates drho/dt (free surfaces truncate no sum); SUMMATION is rho = sum m W.
enum class density_method { continuity, summation };
/// LAMINAR: Morris, Fox & Zhu (1997) with the dynamic viscosity; ARTIFICIAL: Monaghan (1992)
/// Pi_ab = -alpha h c (v.r) / (rho (r^2 + 0.01 h^2)) on approaching pairs (free-surface flows).
enum class viscosity_model { laminar, artificial };
/// Walls: NO_SLIP (the wall velocity extrapolated, Adami et al. 2012 eqs. 22-23) or FREE_SLIP.
enum class wall_condition { no_slip, free_slip };

struct fluid_settings {
  physics::tait eos{};
  density_method density = density_method::continuity;
  /// delta of the Molteni & Colagrossi (2009) diffusion (0: off), hydrostatic part subtracted.
  double delta = 0.1;
  viscosity_model viscosity = viscosity_model::laminar;
  double dynamic_viscosity = 0;               ///< mu = rho0 nu (laminar)
  double artificial_alpha = 0.01;             ///< alpha (artificial)
  std::array<double, 3> body_force{0, 0, 0};  ///< g (acceleration, zeros beyond D)
  double viscous_factor = 0.125;              ///< dt <= factor h^2 / nu
  wall_condition walls = wall_condition::no_slip;
  /// The largest speed the problem expects (its key or its estimate): c0 must exceed it tenfold.
  double expected_speed = 0;

  double kinematic_viscosity() const { return dynamic_viscosity / eos.reference_density; }
};

const flecsi_lite::runtime::name_table<density_method>& density_method_names();
const flecsi_lite::runtime::name_table<viscosity_model>& viscosity_model_names();
const flecsi_lite::runtime::name_table<wall_condition>& wall_condition_names();

/// The keys rho0, c0, background_pressure, density_method, delta_sph, fluid_viscosity,
/// dynamic_viscosity, artificial_viscosity_alpha, body_force_x/y/z, viscous_factor, wall_condition.
const flecsi_lite::runtime::parameter_block<fluid_settings>& fluid_parameters();

/// Warns (rank 0) when c0 < 10 times the expected largest speed, naming both, and throws a
/// parameter_error when c0 is not above it at all.
void check_sound_speed(const std::string& program, const fluid_settings& settings);

}  // namespace flecsph::fluid
