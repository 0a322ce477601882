// The checks of a cubic lattice (cubic_lattice_checks.hh).
#include "cubic_lattice_checks.hh"

#include "flecsi_lite/runtime.hh"

#include <cmath>

namespace lattices {

double check_cubic_lattice(const std::string& program, const cubic_lattice& lattice, double eta, int dimension) {
  using flecsi_lite::runtime::checked_length;
  using flecsi_lite::runtime::checked_positive;
  const std::string lattice_keys = "box_side, particles_per_side";
  flecsi_lite::runtime::checked_particles(program, std::pow(double(lattice.per_side), dimension),
                                          "particles_per_side, dimension");
  const double spacing = checked_length(
    program, "lattice spacing",
    checked_length(program, "box side", lattice.side, "box_side") / double(lattice.per_side), lattice_keys);
  checked_length(program, "smoothing length", eta * spacing, "eta, " + lattice_keys);
  checked_positive(program, "particle mass", lattice.rho0 * std::pow(spacing, dimension), "rho0, " + lattice_keys);
  return spacing;
}

}  // namespace lattices
