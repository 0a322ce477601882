// The keys, layout and particles of the fluid app's problems (fluid_problem.hh).
#include "fluid_problem.hh"

#include "specialization/physics.hh"

#include <algorithm>
#include <cmath>
#include <sstream>

namespace fluid_app {

namespace rt = flecsi_lite::runtime;

const rt::name_table<problem_type>& problem_names() {
  static const rt::name_table<problem_type> table{"fluid problem",
                                                  {{"still_tank", problem_type::still_tank},
                                                   {"poiseuille", problem_type::poiseuille},
                                                   {"couette", problem_type::couette},
                                                   {"dam_break", problem_type::dam_break}}};
  return table;
}

namespace {
rt::parameter_block<problem> declare() {
  rt::parameter_block<problem> p;
  p.choice("problem", &problem::type, problem_names(), "still_tank, poiseuille, couette or dam_break");
  p.integer("dimension", &problem::dimension, "space dimension (2; 3 for the dam break)").range(2, 3);
  p.integer("particles", &problem::particles, "fluid particles across the reference length").range(4, 100000);
  p.real("length", &problem::length, "reference length: depth H, channel width L, column width L")
    .greater_than(0)
    .at_most(1e10);
  p.real("h_factor", &problem::h_factor, "h = h_factor dx").range(0.5, 3);
  p.integer("wall_layers", &problem::wall_layers, "wall particle layers (0: enough for the support 2 h)").range(0, 100);
  p.real("lid_velocity", &problem::lid_velocity, "couette: velocity of the lid").range(-1e10, 1e10);
  p.real("channel_length", &problem::channel_length, "channels: period along x (0: L / 2)").range(0, 1e10);
  p.real("tank_width", &problem::tank_width, "still tank: width (0: 2 H)").range(0, 1e10);
  p.real("column_offset", &problem::column_offset, "shift of the fluid along x (0: at the left wall)")
    .range(-1e10, 1e10);
  p.real("span", &problem::span, "3D dam break: periodic width along z (0: 7 dx)").range(0, 1e10);
  p.real("column_width", &problem::column_width, "dam break: the column's width (units of length)")
    .greater_than(0)
    .at_most(1e6);
  p.real("column_height", &problem::column_height, "dam break: the column's height (units of length)")
    .greater_than(0)
    .at_most(1e6);
  p.real("tank_length", &problem::tank_length,
         "dam break: the tank's inner length (units of length; rounded down to whole spacings)")
    .greater_than(0)
    .at_most(1e6);
  p.real("tank_height", &problem::tank_height, "dam break: the tank's inner height (units of length)")
    .greater_than(0)
    .at_most(1e6);
  return p;
}

std::string text(double value) {
  std::ostringstream s;
  s.precision(6);
  s << value;
  return s.str();
}
}  // namespace

const rt::parameter_block<problem>& problem_parameters() {
  static const auto block = declare();
  return block;
}

layout layout_of(const std::string& program, const problem& p, flecsph::fluid::fluid_settings& fluid) {
  layout l;
  l.dimension = p.dimension;
  const double L = p.length;
  l.dx = L / double(p.particles);
  l.h = p.h_factor * l.dx;
  const double support = flecsph::physics::kernel_support * l.h;
  const auto needed = static_cast<std::int64_t>(std::ceil(support / l.dx - 1e-12));
  l.layers = p.wall_layers ? p.wall_layers : needed;
  if (double(l.layers) * l.dx < support - 1e-12 * l.dx)
    throw rt::parameter_error(program + ": wall_layers = " + std::to_string(l.layers) + " (" +
                              text(double(l.layers) * l.dx) +
                              " thick) is thinner than the kernel support 2 h = " + text(support) +
                              " (h_factor = " + text(p.h_factor) + "): at least " + std::to_string(needed) + " layers");
  if (p.dimension == 3 && p.type != problem_type::dam_break)
    throw rt::parameter_error(program + ": dimension = 3 is for problem = dam_break only, not " +
                              problem_names().name(p.type));
  const double g = std::sqrt(fluid.body_force[0] * fluid.body_force[0] + fluid.body_force[1] * fluid.body_force[1] +
                             fluid.body_force[2] * fluid.body_force[2]);
  const double nu = fluid.kinematic_viscosity();
  switch (p.type) {
    case problem_type::still_tank: {
      const double width = p.tank_width > 0 ? p.tank_width : 2 * L;
      l.fluid_lo = {p.column_offset, 0}, l.fluid_hi = {p.column_offset + width, L};
      l.tank_lo = {0, 0}, l.tank_hi = {width, 1.5 * L};
      l.speed_scale = std::sqrt(g * L);
      break;
    }
    case problem_type::dam_break: {
      l.fluid_lo = {p.column_offset, 0}, l.fluid_hi = {p.column_offset + p.column_width * L, p.column_height * L};
      // The tank's length a whole number of spacings, so that the end walls' lattice continues the
      // floor's (TrixiParticles rounds 5.366 H down the same way); 4 L is one already.
      const double spacings = p.tank_length * double(p.particles);
      const double whole = std::floor(spacings + 1e-9);
      const double tank_length = std::fabs(spacings - whole) <= 1e-9 ? p.tank_length * L : whole * l.dx;
      l.tank_lo = {0, 0}, l.tank_hi = {tank_length, p.tank_height * L};
      l.speed_scale = std::sqrt(2 * g * p.column_height * L);  // the front's speed, sqrt(2 g H)
      if (!(l.fluid_hi[1] <= l.tank_hi[1] * (1 + 1e-12)))
        throw rt::parameter_error(program + ": column_height = " + text(p.column_height) +
                                  " is above tank_height = " + text(p.tank_height));
      if (p.dimension == 3) {
        // A whole number of spacings, so that the periodic lattice is uniform; the search needs
        // a period above twice the interaction radius 2 h (ntree periodic reach).
        const auto layers_z = std::max<std::int64_t>(1, std::llround((p.span > 0 ? p.span : 7 * l.dx) / l.dx));
        l.tank_hi[2] = l.fluid_hi[2] = double(layers_z) * l.dx;
        if (!(l.tank_hi[2] > 2 * support * (1 + 1e-9)))
          throw rt::parameter_error(program + ": span = " + text(p.span) + " (" + std::to_string(layers_z) +
                                    " spacings) is not wider than twice the kernel support 2 (2 h) = " +
                                    text(2 * support) + ": the periodic images would overlap");
      }
      break;
    }
    case problem_type::poiseuille:
    case problem_type::couette: {
      const double period = p.channel_length > 0 ? p.channel_length : 0.5 * L;
      l.periodic_x = true;
      l.top_wall = true;
      l.fluid_lo = {0, 0}, l.fluid_hi = {period, L};
      l.tank_lo = {0, 0}, l.tank_hi = {period, L};
      if (p.type == problem_type::poiseuille) {
        if (!(nu > 0)) throw rt::parameter_error(program + ": poiseuille needs dynamic_viscosity > 0");
        l.speed_scale = std::fabs(fluid.body_force[0]) * L * L / (8 * nu);
      } else {
        l.speed_scale = std::fabs(p.lid_velocity);
      }
      break;
    }
  }
  if (!l.periodic_x && (l.fluid_lo[0] < l.tank_lo[0] - 1e-12 * L || l.fluid_hi[0] > l.tank_hi[0] + 1e-12 * L))
    throw rt::parameter_error(program + ": column_offset = " + text(p.column_offset) +
                              " puts fluid particles inside a wall: the fluid spans x in [" + text(l.fluid_lo[0]) +
                              ", " + text(l.fluid_hi[0]) + "], the tank's inside [" + text(l.tank_lo[0]) + ", " +
                              text(l.tank_hi[0]) + "]");
  // The fluid block's lattice (the walls come on top of it) must fit in the job's memory.
  double fluid_count = 1;
  for (int k = 0; k < p.dimension; ++k)
    fluid_count *= std::max(1.0, std::floor((l.fluid_hi[k] - l.fluid_lo[k]) / l.dx * (1 + 1e-12)));
  const std::string extent_keys =
    p.type == problem_type::dam_break
      ? (p.dimension == 3 ? "column_width, column_height, span" : "column_width, column_height")
    : p.type == problem_type::still_tank ? "tank_width"
                                         : "channel_length";
  rt::checked_particles(program, fluid_count, "particles, " + extent_keys);
  fluid.expected_speed = l.speed_scale;
  flecsph::fluid::check_sound_speed(program, fluid);
  return l;
}

std::vector<particle> particles_of(const problem& p, const layout& l, const flecsph::fluid::fluid_settings& fluid) {
  std::vector<particle> out;
  const double dx = l.dx, volume = l.dimension == 3 ? dx * dx * dx : dx * dx, rho0 = fluid.eos.reference_density;
  const double g = -fluid.body_force[1];  // gravity along -y (hydrostatic start)
  const double depth = l.fluid_hi[1];
  const auto count = [dx](double lo, double hi) { return static_cast<std::int64_t>(std::llround((hi - lo) / dx)); };
  // 2D: one z layer at z = 0; 3D: the 2D lattice repeated at z = (l + 1/2) dx across the span.
  const std::int64_t nz = l.dimension == 3 ? count(l.tank_lo[2], l.tank_hi[2]) : 1;
  const auto z_of = [&](std::int64_t layer) {
    return l.dimension == 3 ? l.tank_lo[2] + (double(layer) + 0.5) * dx : 0.0;
  };
  const auto add = [&](double x, double y, double m, double rho, bool wall, double lid) {
    for (std::int64_t layer = 0; layer < nz; ++layer) out.push_back({{x, y, z_of(layer)}, m, rho, wall, {lid, 0, 0}});
  };
  const std::int64_t nx = count(l.fluid_lo[0], l.fluid_hi[0]), ny = count(l.fluid_lo[1], l.fluid_hi[1]);
  for (std::int64_t j = 0; j < ny; ++j)
    for (std::int64_t i = 0; i < nx; ++i) {
      const double x = l.fluid_lo[0] + (double(i) + 0.5) * dx, y = l.fluid_lo[1] + (double(j) + 0.5) * dx;
      const double rho = fluid.eos.density(fluid.eos.background_pressure + rho0 * g * (depth - y));
      add(x, y, rho * volume, rho, false, 0);
    }
  const double wall_mass = rho0 * volume;
  const std::int64_t n = l.layers;
  const std::int64_t tank_nx = count(l.tank_lo[0], l.tank_hi[0]), tank_ny = count(l.tank_lo[1], l.tank_hi[1]);
  const std::int64_t first = l.periodic_x ? 0 : -n, last = l.periodic_x ? tank_nx : tank_nx + n;
  // Bottom (and for channels top) layers, corners included.
  for (std::int64_t k = 0; k < n; ++k)
    for (std::int64_t i = first; i < last; ++i)
      add(l.tank_lo[0] + (double(i) + 0.5) * dx, l.tank_lo[1] - (double(k) + 0.5) * dx, wall_mass, rho0, true, 0);
  if (l.top_wall) {
    const double lid = p.type == problem_type::couette ? p.lid_velocity : 0.0;
    for (std::int64_t k = 0; k < n; ++k)
      for (std::int64_t i = first; i < last; ++i)
        add(l.tank_lo[0] + (double(i) + 0.5) * dx, l.tank_hi[1] + (double(k) + 0.5) * dx, wall_mass, rho0, true, lid);
  }
  if (!l.periodic_x)
    for (std::int64_t j = 0; j < tank_ny; ++j)
      for (std::int64_t k = 0; k < n; ++k) {
        const double y = l.tank_lo[1] + (double(j) + 0.5) * dx;
        add(l.tank_lo[0] - (double(k) + 0.5) * dx, y, wall_mass, rho0, true, 0);
        add(l.tank_hi[0] + (double(k) + 0.5) * dx, y, wall_mass, rho0, true, 0);
      }
  return out;
}

}  // namespace fluid_app
