// The liquid problems of the fluid app (square or cubic lattice of spacing dx, Adami et al. 2012
// dummy walls in layers): a still tank (hydrostatics), plane Poiseuille and Couette flow (periodic
// along x), and the dam break of Martin & Moyce (1952) or of Lobovsky et al. (2014) (the keys
// column_* and tank_*), also in 3D (periodic along the span z): the parameters and the particles.
#pragma once

#include "specialization/fluid.hh"
#include "specialization/sph.hh"

#include "flecsi_lite/runtime.hh"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace fluid_app {

enum class problem_type { still_tank, poiseuille, couette, dam_break };
const flecsi_lite::runtime::name_table<problem_type>& problem_names();

struct problem {
  problem_type type = problem_type::dam_break;
  int dimension = 2;
  /// Fluid particles across the reference length: the depth H (tank), the width L (channels),
  /// the column width L (dam break).
  std::int64_t particles = 50;
  double length = 1;             ///< the reference length (m)
  double h_factor = 1.5;         ///< h = h_factor dx (docs/fluid-flow.md: the lattice moment)
  std::int64_t wall_layers = 0;  ///< 0: enough to cover the kernel support 2 h
  double lid_velocity = 1e-5;    ///< couette: v0 of the lid at y = L
  double channel_length = 0;     ///< channels: the period along x (0: L / 2)
  double tank_width = 0;         ///< still tank: width (0: 2 H)
  double column_offset = 0;      ///< shifts the fluid along x (0: touching the left wall)
  double span = 0;               ///< 3D dam break: the periodic width along z (0: 7 dx)
  /// Dam break geometry in units of `length`: the column (Martin & Moyce 1952: 1 x 2; Lobovsky
  /// et al. 2014 and Marrone et al. 2011, with length = H: 2 x 1) and the tank (4 x 3; 5.366 x 4).
  double column_width = 1, column_height = 2, tank_length = 4, tank_height = 3;
};

const flecsi_lite::runtime::parameter_block<problem>& problem_parameters();

/// The lattice and the fluid and tank boxes derived from the keys.
struct layout {
  int dimension = 2;
  double dx = 0, h = 0;
  std::int64_t layers = 0;
  std::array<double, 3> fluid_lo{}, fluid_hi{};  ///< fluid block (z: 3D only)
  std::array<double, 3> tank_lo{}, tank_hi{};    ///< inside of the walls (channels: lo.y, hi.y only)
  bool periodic_x = false, top_wall = false;     ///< 3D: always periodic along z, tank_lo.z to tank_hi.z
  double speed_scale = 0;                        ///< the flow's expected largest speed
};

/// The layout; parameter_errors name the keys: wall layers thinner than the support 2 h, a fluid
/// particle inside a wall (column_offset), c0 not above the speed scale (check_sound_speed),
/// dimension 3 but for the dam break, a span narrower than twice the interaction radius 4 h.
layout layout_of(const std::string& program, const problem& p, flecsph::fluid::fluid_settings& fluid);

struct particle {
  std::array<double, 3> x;
  double m, rho;
  bool wall;
  std::array<double, 3> wall_velocity;
};
/// Every particle of the problem in a fixed order (fluid, then walls; in 3D each 2D lattice row
/// repeated along z); fluid in hydrostatic equilibrium rho(y) = rho(P = rho0 |g| (H - y) + P_b),
/// m = rho dx^D; walls m = rho0 dx^D.
std::vector<particle> particles_of(const problem& p, const layout& l, const flecsph::fluid::fluid_settings& fluid);

}  // namespace fluid_app
