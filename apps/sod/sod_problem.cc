// The Sod shock tube's parameter keys (declared once), particle layout and initial particles
// (sod_problem.hh).
#include "sod_problem.hh"

#include "flecsi_lite/runtime.hh"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <string>
#include <type_traits>

namespace sod {

const flecsi_lite::runtime::name_table<lattice_type>& lattice_names() {
  static const flecsi_lite::runtime::name_table<lattice_type> table{
    "lattice", {{"body_centred", lattice_type::body_centred}, {"cubic", lattice_type::cubic}}};
  return table;
}

namespace {
flecsi_lite::runtime::parameter_block<problem> declare_problem() {
  flecsi_lite::runtime::parameter_block<problem> tube;
  tube.integer("dimension", &problem::dimension, "space dimension of the tube (2, 3: periodic transverse axes)")
    .range(1, 3);
  tube
    .integer("particles", &problem::particles,
             "1D: fluid particles (equal masses); 2D/3D: mean particle spacings along x on the left")
    .at_least(2);
  tube.choice("lattice", &problem::lattice, lattice_names(), "2D/3D: lattice of the particles");
  tube.real("rho_left", &problem::rho_left, "density left of the interface").greater_than(0);
  tube.real("p_left", &problem::p_left, "pressure left of the interface").greater_than(0);
  tube.real("rho_right", &problem::rho_right, "density right of the interface").greater_than(0);
  tube.real("p_right", &problem::p_right, "pressure right of the interface").greater_than(0);
  tube.real("x_min", &problem::x_min, "left end of the tube (a wall)");
  tube.real("x_interface", &problem::x_interface, "initial position of the discontinuity");
  tube.real("x_max", &problem::x_max, "right end of the tube (a wall)");
  tube.real("tube_width", &problem::width, "2D/3D: period of the transverse axes (0: about 8 mean particle spacings)")
    .at_least(0);
  tube
    .integer("wall_layers", &problem::wall_layers,
             "fixed wall particles at each end (0: as many as the kernel reaches)")
    .at_least(0);
  tube.real("l1_window", &problem::window, "L1 errors over the particles with |x - x_interface| < l1_window")
    .greater_than(0);
  tube.check([](const problem& p) {
    if (!(p.x_min < p.x_interface && p.x_interface < p.x_max))
      throw flecsi_lite::runtime::parameter_error("sod: x_min < x_interface < x_max is required");
  });
  return tube;
}
}  // namespace

const flecsi_lite::runtime::parameter_block<problem>& problem_parameters() {
  static const auto block = declare_problem();
  return block;
}

namespace {
using flecsi_lite::runtime::checked_count;
using flecsi_lite::runtime::checked_length;
using flecsi_lite::runtime::checked_positive;

// The keys each derived quantity comes from, named in the errors of its checks.
const std::string left_keys = "x_min, x_interface", right_keys = "x_interface, x_max";
const std::string tube_keys = "particles, rho_left, rho_right, x_min, x_interface, x_max";

/// A side's particle count (1D) or layers (2D/3D) from `value`: at least one, else the density
/// contrast is more than `particles` can resolve (silently one particle there would mean a
/// tube of millions of particles on the other side, which looked like a hang at step 0).
std::int64_t resolved_count(const problem& problem, const std::string& what, double value) {
  const std::int64_t count = checked_count("sod", what, value, tube_keys);
  if (count >= 1) return count;
  std::ostringstream message;
  message.precision(6);
  message << "sod: " << what << " = " << value << " (from " << tube_keys << "): particles = " << problem.particles
          << " cannot resolve the density contrast rho_left / rho_right = " << problem.rho_left / problem.rho_right
          << "; raise particles to at least " << std::ceil(double(problem.particles) / std::max(value, 1e-300))
          << " or lower the contrast";
  throw flecsi_lite::runtime::parameter_error(message.str());
}

/// Smoothing length of a particle of mass m at density rho.
double initial_h(const sph::physics_settings& physics, int dimension, double m, double rho) {
  return physics.eta * std::pow(m / rho, 1.0 / dimension);
}

/// Wall layers: a fluid particle next to a wall reaches 2 (1 + margin) h of walls, and those
/// walls need the same depth of walls behind them for a complete density sum.
std::int64_t wall_layers(const problem& problem, const sph::physics_settings& physics, double h, double spacing) {
  if (problem.wall_layers > 0) return checked_count("sod", "wall layers", double(problem.wall_layers), "wall_layers");
  const double reach = 2 * flecsph::physics::kernel_support * (1 + physics.search_margin) * h / spacing;
  return checked_count("sod", "wall layers (the kernel's reach)", std::ceil(reach) + 2,
                       "eta, search_margin, " + tube_keys);
}

/// Every count, length, mass and energy of `layout` (and the particles' internal energies) in
/// range: no count can overflow and no position, mass or energy is infinite or zero.
void check_layout(const problem& problem, const sph::physics_settings& physics, const tube_layout& layout) {
  const double layer_left = std::pow(double(layout.across_left), layout.dimension - 1);
  const double layer_right = std::pow(double(layout.across_right), layout.dimension - 1);
  checked_count("sod", "particles per layer on the left", layer_left, "tube_width, " + tube_keys);
  checked_count("sod", "particles per layer on the right", layer_right, "tube_width, " + tube_keys);
  const double particles =
    double(layout.walls_left + layout.left) * layer_left + double(layout.right + layout.walls_right) * layer_right;
  flecsi_lite::runtime::checked_particles("sod", particles,
                                          "wall_layers, search_margin, eta, tube_width, " + tube_keys);
  checked_positive("sod", "particle mass", layout.mass, tube_keys);
  checked_length("sod", "spacing along x on the left", layout.spacing_left, tube_keys);
  checked_length("sod", "spacing along x on the right", layout.spacing_right, tube_keys);
  checked_length("sod", "smoothing length on the left",
                 initial_h(physics, layout.dimension, layout.mass, problem.rho_left), "eta, " + tube_keys);
  checked_length("sod", "smoothing length on the right",
                 initial_h(physics, layout.dimension, layout.mass, problem.rho_right), "eta, " + tube_keys);
  // The particles' extent beyond the interface on each side, walls included (the domain's box).
  const double reach_left = double(layout.left + layout.walls_left + 1) * layout.spacing_left;
  const double reach_right = double(layout.right + layout.walls_right + 1) * layout.spacing_right;
  checked_length("sod", "extent of the particles left of the interface", reach_left, "wall_layers, " + tube_keys);
  checked_length("sod", "extent of the particles right of the interface", reach_right, "wall_layers, " + tube_keys);
  checked_length("sod", "extent of the tube with its walls", reach_left + reach_right, "wall_layers, " + tube_keys);
  checked_length("sod", "farthest coordinate of a particle",
                 std::fabs(problem.x_interface) + std::max(reach_left, reach_right), "wall_layers, " + tube_keys);
  const auto& gas = physics.eos.ideal;
  checked_positive("sod", "internal energy on the left", gas.internal_energy(problem.rho_left, problem.p_left),
                   "rho_left, p_left, gamma");
  checked_positive("sod", "internal energy on the right", gas.internal_energy(problem.rho_right, problem.p_right),
                   "rho_right, p_right, gamma");
}
}  // namespace

tube_layout layout_of(const problem& problem, const sph::physics_settings& physics, int dimension) {
  tube_layout layout;
  layout.dimension = dimension;
  const double length_left =
    checked_length("sod", "length left of the interface", problem.x_interface - problem.x_min, left_keys);
  const double length_right =
    checked_length("sod", "length right of the interface", problem.x_max - problem.x_interface, right_keys);
  if (dimension == 1) {
    const double mass_left =
      checked_positive("sod", "mass left of the interface", problem.rho_left * length_left, "rho_left, " + left_keys);
    const double mass_right = checked_positive("sod", "mass right of the interface", problem.rho_right * length_right,
                                               "rho_right, " + right_keys);
    const double total = checked_positive("sod", "mass of the tube", mass_left + mass_right, tube_keys);
    const double right = double(problem.particles) * mass_right / total;
    layout.right = resolved_count(problem, "particles right of the interface", right);
    const double left = double(layout.right) * mass_left / mass_right;
    layout.left = resolved_count(problem, "particles left of the interface", left);
    layout.mass = total / double(layout.left + layout.right);
  } else {
    layout.body_centred = problem.lattice == lattice_type::body_centred;
    // Mean spacings (m/rho)^(1/D) and cells (of 2 particles when body-centred) on each side.
    const double spacing_left =
      checked_length("sod", "mean spacing on the left", length_left / double(problem.particles), tube_keys);
    const double contrast = std::pow(problem.rho_left / problem.rho_right, 1.0 / dimension);
    const double spacing_right = checked_length("sod", "mean spacing on the right", spacing_left * contrast, tube_keys);
    const double cell = std::pow(layout.body_centred ? 2.0 : 1.0, 1.0 / dimension);
    const double cell_left = cell * spacing_left, cell_right = cell * spacing_right;
    // Wide enough that the reach 2 (1 + margin) h stays below half the period as h grows: about
    // 8 mean spacings of the coarser side, in whole cells of that side.
    const double coarse_cell = cell * std::max(spacing_left, spacing_right);
    layout.width = checked_length("sod", "transverse period",
                                  problem.width > 0 ? problem.width : double(std::llround(8 / cell)) * coarse_cell,
                                  "tube_width, " + tube_keys);
    layout.across_left = std::max<std::int64_t>(
      1, checked_count("sod", "particles across on the left", layout.width / cell_left, "tube_width, " + tube_keys));
    layout.across_right = std::max<std::int64_t>(
      1, checked_count("sod", "particles across on the right", layout.width / cell_right, "tube_width, " + tube_keys));
    layout.across_spacing_left = layout.width / double(layout.across_left);
    layout.across_spacing_right = layout.width / double(layout.across_right);
    layout.mass = problem.rho_left * std::pow(spacing_left, dimension);
  }
  checked_positive("sod", "particle mass", layout.mass, tube_keys);
  const auto across_area = [&](double across) { return std::pow(across, dimension - 1); };
  layout.spacing_left = layout.mass / (problem.rho_left * across_area(layout.across_spacing_left));
  layout.spacing_right = layout.mass / (problem.rho_right * across_area(layout.across_spacing_right));
  if (dimension == 1) {
    layout.spacing_left = layout.mass / problem.rho_left;
    layout.spacing_right = layout.mass / problem.rho_right;
  } else {
    checked_length("sod", "spacing along x on the left", layout.spacing_left, "tube_width, " + tube_keys);
    checked_length("sod", "spacing along x on the right", layout.spacing_right, "tube_width, " + tube_keys);
    layout.left = resolved_count(problem, "layers left of the interface", length_left / layout.spacing_left);
    layout.right = resolved_count(problem, "layers right of the interface", length_right / layout.spacing_right);
  }
  checked_length("sod", "spacing along x on the left", layout.spacing_left, tube_keys);
  checked_length("sod", "spacing along x on the right", layout.spacing_right, tube_keys);
  layout.walls_left =
    wall_layers(problem, physics, initial_h(physics, dimension, layout.mass, problem.rho_left), layout.spacing_left);
  layout.walls_right =
    wall_layers(problem, physics, initial_h(physics, dimension, layout.mass, problem.rho_right), layout.spacing_right);
  check_layout(problem, physics, layout);
  const auto consistent = [&](double rho, double along, double across) {
    const double volume = layout.mass / rho, shift = layout.body_centred ? 0.5 : 0.0;
    const auto sum = [&](auto dimension_tag) {
      constexpr int D = decltype(dimension_tag)::value;
      return sph::density_consistent_particle<D>(physics, rho, volume, [&](double h) {
        return sph::lattice_kernel_sum<D>(physics.kernel, h, along, across, shift);
      });
    };
    return dimension == 1   ? sum(std::integral_constant<int, 1>{})
           : dimension == 2 ? sum(std::integral_constant<int, 2>{})
                            : sum(std::integral_constant<int, 3>{});
  };
  const auto left = consistent(problem.rho_left, layout.spacing_left, layout.across_spacing_left);
  const auto right = consistent(problem.rho_right, layout.spacing_right, layout.across_spacing_right);
  layout.mass_left = checked_positive("sod", "particle mass on the left", left.mass, "eta, kernel, " + tube_keys);
  layout.mass_right = checked_positive("sod", "particle mass on the right", right.mass, "eta, kernel, " + tube_keys);
  layout.h_left = checked_length("sod", "smoothing length on the left", left.h, "eta, kernel, " + tube_keys);
  layout.h_right = checked_length("sod", "smoothing length on the right", right.h, "eta, kernel, " + tube_keys);
  return layout;
}

tube_particle particle_of(const problem& problem, const sph::physics_settings& /*physics*/, const tube_layout& layout,
                          std::int64_t index) {
  tube_particle particle{};
  const std::int64_t left_count = (layout.walls_left + layout.left) * layout.layer_left();
  const bool left = index < left_count;
  const std::int64_t layer_size = left ? layout.layer_left() : layout.layer_right();
  const std::int64_t local = left ? index : index - left_count;
  const std::int64_t layer = local / layer_size, cell = local % layer_size;
  // Layers counted from the interface outwards.
  const std::int64_t from_interface = left ? layout.walls_left + layout.left - 1 - layer : layer;
  const double spacing = left ? layout.spacing_left : layout.spacing_right;
  particle.x[0] = problem.x_interface + (left ? -1.0 : 1.0) * (double(from_interface) + 0.5) * spacing;
  const std::int64_t across = left ? layout.across_left : layout.across_right;
  const double across_spacing = left ? layout.across_spacing_left : layout.across_spacing_right;
  // Body-centred: odd layers sit in the middle of the even layers' cells.
  const double offset = layout.body_centred ? (from_interface % 2 ? 0.75 : 0.25) : 0.5;
  std::int64_t rest = cell;
  for (int k = 1; k < layout.dimension; ++k, rest /= across)
    particle.x[k] = (double(rest % across) + offset) * across_spacing - 0.5 * layout.width;
  particle.rho = left ? problem.rho_left : problem.rho_right;
  particle.P = left ? problem.p_left : problem.p_right;
  particle.h = left ? layout.h_left : layout.h_right;
  particle.m = left ? layout.mass_left : layout.mass_right;
  particle.kind =
    from_interface < (left ? layout.left : layout.right) ? sph::particle_kind::fluid : sph::particle_kind::wall;
  return particle;
}

}  // namespace sod
