// The checks of a cubic lattice that fills a box (the sedov and noh apps): the quantities its
// keys imply (particle count, spacing, smoothing length, particle mass), each a parameter_error
// (exit status 2) naming the keys it comes from (flecsi_lite/runtime/derived_values.hh).
#pragma once

#include <cstdint>
#include <string>

namespace lattices {

/// A box of side `side` filled by `per_side`^dimension particles (keys box_side,
/// particles_per_side) of density `rho0` (key rho0), smoothing length eta times the spacing.
struct cubic_lattice {
  std::int64_t per_side = 0;
  double side = 0;
  double rho0 = 0;
};

/// Checks `lattice` for `program`'s messages; returns the lattice spacing side / per_side.
double check_cubic_lattice(const std::string& program, const cubic_lattice& lattice, double eta, int dimension);

}  // namespace lattices
