// Glass initial conditions for the problems (sedov, noh: `initial_lattice = glass`): the cached
// glass of the glass app (a periodic unit box of n^D equal-mass particles, glass.cc) read on every
// rank and tiled periodically over the problem's box, as SWIFT's examples replicate a small
// glass (e.g. examples/HydroTests/SedovBlast_3D: glassCube_64.hdf5 tiled). The tiles repeat the
// glass exactly, so the tiling adds a (weak) periodicity of one glass side; docs/glass.md.
#pragma once

#include "specialization/sph.hh"

#include "flecsi_lite/io.hh"
#include "flecsi_lite/runtime.hh"

#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace glass {
namespace sph = flecsph::sph;

/// The cache file of a glass: glass_<D>d_<n>_<kernel>_eta<eta>.h5part (eta with 6 significant digits).
std::string cache_name(int dimension, std::int64_t per_side, const std::string& kernel, double eta);

/// The root attributes a glass file carries, by which a reader checks it is the glass it asked for.
flecsi_lite::io::run_state glass_attributes(std::int64_t per_side, const sph::physics_settings& physics);

enum class start_layout { lattice, glass };
const flecsi_lite::runtime::name_table<start_layout>& layout_names();

/// The keys of a problem that may start from a glass.
struct layout_settings {
  start_layout layout = start_layout::lattice;
  std::string glass_file = "auto";  ///< auto: cache_name(...) of glass_per_side, the run's kernel and eta
  std::int64_t glass_per_side = 16;
};
const flecsi_lite::runtime::parameter_block<layout_settings>& layout_parameters();

/// Positions in [0, 1)^D of the glass, the same on every rank.
template<int D>
struct unit_glass {
  std::vector<sph::vector<D>> positions;
  std::int64_t per_side = 0;
};

/// Reads the last step of the glass file of `settings` (its own name or the cache name), on every
/// rank. A missing file is a runtime error (exit 3) that prints the command making it; a file
/// whose dimension, particle count, kernel or eta differ from the run's is one naming both. Collective.
template<int D>
unit_glass<D> read_glass(const layout_settings& settings, const sph::physics_settings& physics);

/// Checks that `problem_per_side` (the problem's particles per side) is a multiple of glass_per_side;
/// throws parameter_error naming the keys otherwise. Returns the tiles per side.
std::int64_t tiles_per_side(const layout_settings& settings, std::int64_t problem_per_side, const std::string& program);

/// Position of particle `index` of the tiled glass in the box [lo, lo + side)^D: tile index / N
/// (its D coordinates in tiles, first axis fastest), glass particle index % N.
template<int D>
sph::vector<D> tiled_position(const unit_glass<D>& glass, std::int64_t tiles, double lo, double side,
                              std::uint64_t index) {
  const std::uint64_t count = glass.positions.size();
  std::uint64_t tile = index / count;
  const auto& inside = glass.positions[index % count];
  const double tile_side = side / double(tiles);
  sph::vector<D> x;
  for (int k = 0; k < D; ++k, tile /= static_cast<std::uint64_t>(tiles))
    x[k] = lo + (double(tile % static_cast<std::uint64_t>(tiles)) + inside[k]) * tile_side;
  return x;
}

/// A glass tiled tiles^D times over a problem's box.
template<int D>
struct tiling {
  unit_glass<D> glass;
  std::int64_t tiles = 1;
  /// Particle `index` in the box [lo, lo + side)^D.
  sph::vector<D> position(double lo, double side, std::uint64_t index) const {
    return tiled_position(glass, tiles, lo, side, index);
  }
  /// The particles of a glass start: mass rho V / N (equal masses), h = eta (V / N)^(1/D).
  sph::lattice_particle particle(const sph::physics_settings& physics, double rho, double spacing) const {
    return {rho * std::pow(spacing, D), physics.eta * spacing};
  }
};

/// The tiling of a problem of `per_side` particles per side when `settings` choose the glass (read
/// here, collective); nullopt for the lattice.
template<int D>
std::optional<tiling<D>> choose_tiling(const layout_settings& settings, const sph::physics_settings& physics,
                                       std::int64_t per_side, const std::string& program) {
  if (settings.layout != start_layout::glass) return std::nullopt;
  const auto tiles = tiles_per_side(settings, per_side, program);
  return tiling<D>{read_glass<D>(settings, physics), tiles};
}

extern template unit_glass<2> read_glass<2>(const layout_settings&, const sph::physics_settings&);
extern template unit_glass<3> read_glass<3>(const layout_settings&, const sph::physics_settings&);

}  // namespace glass
