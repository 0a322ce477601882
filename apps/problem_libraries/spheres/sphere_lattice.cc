// The ball lattice and its radial stretch (sphere_lattice.hh).
#include "sphere_lattice.hh"

#include <algorithm>
#include <cmath>

namespace spheres {

std::vector<site> ball_lattice(std::int64_t particles) {
  const double pi = std::acos(-1.0);
  const double side = std::cbrt(8.0 * pi / (3.0 * double(particles)));
  const auto cells = static_cast<long>(std::ceil(1.0 / side)) + 1;
  std::vector<site> sites;
  sites.reserve(static_cast<std::size_t>(1.1 * double(particles)) + 16);
  // Corners at (i, j, k) a, centres at (i + 1/2, j + 1/2, k + 1/2) a.
  for (long i = -cells; i <= cells; ++i)
    for (long j = -cells; j <= cells; ++j)
      for (long k = -cells; k <= cells; ++k)
        for (const double shift : {0.0, 0.5}) {
          const site x{(double(i) + shift) * side, (double(j) + shift) * side, (double(k) + shift) * side};
          if (radius(x) <= 1.0) sites.push_back(x);
        }
  // The ball holds a few sites more or fewer than its volume times the lattice's density: scaled
  // so that it does not (N sites of the density 2 / a^3 fill the volume 4 pi / 3), a sphere of
  // N particles of mass M / N has the mean density 3 M / (4 pi R^3) inside.
  const double scale = std::cbrt(3.0 * double(sites.size()) * side * side * side / (8.0 * pi));
  for (auto& x : sites)
    for (double& component : x) component /= scale;
  return sites;
}

site stretch_to_inverse_r(const site& x) {
  const double r = radius(x);
  const double factor = std::sqrt(r);  // r^(3/2) / r
  return {x[0] * factor, x[1] * factor, x[2] * factor};
}

double radius(const site& x) { return std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]); }

double fraction_radius(const radial_mass& bins, double r_max, double fraction) {
  double total = bins.outside;
  for (const double m : bins.mass) total += m;
  const double target = fraction * total;
  double below = 0;
  for (int i = 0; i < bin_count; ++i) {
    const double mass = bins.mass[static_cast<std::size_t>(i)];
    if (mass > 0 && below + mass >= target) return (i + (target - below) / mass) * r_max / bin_count;
    below += mass;
  }
  return r_max;
}

double fraction_radius(const std::vector<site>& sites, double fraction) {
  double largest = 0;
  for (const auto& x : sites) largest = std::max(largest, radius(x));
  const double r_max = 1.000001 * largest;
  radial_mass bins;
  for (const auto& x : sites) {
    const auto bin = static_cast<long>(radius(x) / r_max * bin_count);
    if (bin >= bin_count)
      bins.outside += 1;
    else
      bins.mass[static_cast<std::size_t>(std::max(0L, bin))] += 1;
  }
  return fraction_radius(bins, r_max, fraction);
}

}  // namespace spheres
