// Self-gravitating spheres for the SPH specialization (the evrard and cold_collapse apps): a
// body-centred cubic lattice cut to a ball, optionally stretched radially so that the density
// follows 1/r (Evrard 1988), and the radii holding given fractions of the mass.
#pragma once

#include "specialization/sph.hh"

#include "flecsi_lite/execution.hh"

#include <array>
#include <cstdint>
#include <vector>

namespace spheres {
namespace sph = flecsph::sph;

using site = std::array<double, 3>;

/// The sites of a body-centred cubic lattice inside the unit ball, with the cell side chosen so that
/// the ball holds about `particles` sites (2 per cell: a = (8 pi / (3 N))^(1/3)), then scaled so
/// that the N sites it holds have the density N / (4 pi / 3) (the outermost may lie a few tenths
/// of a percent beyond r = 1): equal masses M / N then have the sphere's mean density inside.
/// Cell corners at integer multiples of a (one site at the origin): the set is symmetric under
/// every axis reflection, so its centre of mass is the origin. A fixed order (x slowest), the same
/// on every rank. `particles` >= 1.
std::vector<site> ball_lattice(std::int64_t particles);

/// r -> r^(3/2) on the unit ball: a uniform ball becomes one of density proportional to 1/r with
/// the same mass inside r = 1 (M(<r) = r^2). The lattice is then compressed radially by
/// (3/2) r^(1/2) and tangentially by r^(1/2): locally anisotropic by 3/2 everywhere.
site stretch_to_inverse_r(const site& x);

/// |x|.
double radius(const site& x);

/// Mass in radial bins of width r_max / bin_count around the origin: per-rank sums, combined over
/// ranks (the check's radius need not be bitwise rank-invariant).
inline constexpr int bin_count = 4096;
struct radial_mass {
  std::array<double, bin_count> mass{};
  double outside = 0;  ///< mass beyond r_max
};
struct radial_mass_reduction {
  static radial_mass combine(radial_mass a, const radial_mass& b) {
    for (int i = 0; i < bin_count; ++i) a.mass[i] += b.mass[i];
    a.outside += b.outside;
    return a;
  }
};

inline double largest_radius(sph::ro<sph::vector<3>> x) {
  double largest = 0;
  for (std::size_t a = 0; a < x.size(); ++a) largest = std::max(largest, radius({x(a)[0], x(a)[1], x(a)[2]}));
  return largest;
}

inline radial_mass mass_in_bins(double r_max, sph::ro<sph::vector<3>> x, sph::ro<double> m) {
  radial_mass bins;
  for (std::size_t a = 0; a < x.size(); ++a) {
    const double r = radius({x(a)[0], x(a)[1], x(a)[2]});
    const auto bin = static_cast<long>(r / r_max * bin_count);
    if (bin >= bin_count)
      bins.outside += m(a);
    else
      bins.mass[static_cast<std::size_t>(std::max(0L, bin))] += m(a);
  }
  return bins;
}

/// The radius where the cumulative mass of the bins crosses `fraction` of their total (linear
/// within the bin: resolution r_max / bin_count).
double fraction_radius(const radial_mass& bins, double r_max, double fraction);

/// The same for equal-mass sites (the generated sphere before any step: restarts and initial data
/// alike compare with it), binned as the particles are.
double fraction_radius(const std::vector<site>& sites, double fraction);

/// The radius holding `fraction` of the particles' mass (binned). Collective.
inline double mass_fraction_radius(sph::simulation<3>& s, double fraction) {
  using f = sph::fields<3>;
  auto& p = *s.particles;
  namespace reduction = flecsi_lite::reduction;
  const double r_max = 1.000001 * flecsi_lite::reduce<largest_radius, reduction::max>(f::position()(p)).get();
  const auto bins =
    flecsi_lite::reduce<mass_in_bins, radial_mass_reduction>(r_max, f::position()(p), f::mass()(p)).get();
  return fraction_radius(bins, r_max, fraction);
}

}  // namespace spheres
