// Self-gravitating particle sets and pair functions for the gravity tests and benchmark: uniform
// sphere, Evrard's 1/r profile (Evrard 1988) and the Plummer sphere of particle_sets.hh, and the
// Newtonian pair plain or softened by the cubic spline (Price & Monaghan 2007, MNRAS 374, 1347).
#pragma once

#include "flecsi_lite/topology/ntree/gravity/gravity.hh"
#include "tests/flecsi_lite/topology/ntree/particle_sets.hh"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <random>
#include <string>
#include <vector>

namespace ntree_test {

namespace detail {
// n points of a spherically symmetric distribution of unit mass and radius: radius_of(u) is
// the radius enclosing mass fraction u, density_of(r) the number density per particle.
template<class Radius, class Density>
particle_set<3> sphere(std::size_t n, std::uint64_t seed, const Radius& radius_of, const Density& density_of,
                       double neighbours) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> unit(0, 1);
  particle_set<3> set;
  set.x.resize(n);
  std::vector<double> density(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double r = radius_of(unit(random));
    const double cos_theta = 2 * unit(random) - 1;
    const double sin_theta = std::sqrt(1 - cos_theta * cos_theta);
    const double phi = 2 * M_PI * unit(random);
    set.x[i] = {r * sin_theta * std::cos(phi), r * sin_theta * std::sin(phi), r * cos_theta};
    density[i] = static_cast<double>(n) * density_of(std::max(r, 1e-3));
  }
  set.domain = nt::box<3>::empty();
  finish(set, density, neighbours, random, 0.1);
  return set;
}
}  // namespace detail

/// n points uniform in the unit ball.
inline particle_set<3> uniform_sphere(std::size_t n, std::uint64_t seed, double neighbours = 40) {
  return detail::sphere(
    n, seed, [](double u) { return std::cbrt(u); }, [](double) { return 3 / (4 * M_PI); }, neighbours);
}

/// Evrard's sphere: density 1 / (2 pi r) inside r < 1 (mass r^2 within r).
inline particle_set<3> evrard_sphere(std::size_t n, std::uint64_t seed, double neighbours = 40) {
  return detail::sphere(
    n, seed, [](double u) { return std::sqrt(u); }, [](double r) { return 1 / (2 * M_PI * r); }, neighbours);
}

/// The sets by name: "uniform", "plummer", "evrard".
inline particle_set<3> gravity_set(const std::string& name, std::size_t n, std::uint64_t seed) {
  if (name == "uniform") return uniform_sphere(n, seed);
  if (name == "plummer") return plummer(n, seed);
  return evrard_sphere(n, seed);
}

/// The Newtonian pair {-1/r, 1/r^3}, with the self pair (r = 0) giving nothing.
struct newtonian_pair {
  nt::softened_pair operator()(double r, double, double) const {
    if (r == 0) return {0, 0};
    return {-1 / r, 1 / (r * r * r)};
  }
};

/// The Newtonian pair softened by the M4 cubic spline of softening length 0.5 (h_i + h_j)
/// (support 2 h: Newtonian beyond 2 max(h_i, h_j), symmetric in the two h).
struct spline_pair {
  nt::softened_pair operator()(double r, double hi, double hj) const {
    const double h = 0.5 * (hi + hj);
    if (r >= 2 * h) return {-1 / r, 1 / (r * r * r)};
    const double q = r / h, q2 = q * q, q3 = q2 * q;
    const double h3 = h * h * h;
    if (q < 1) {
      const double potential = (2.0 / 3 * q2 - 0.3 * q2 * q2 + 0.1 * q2 * q3 - 1.4) / h;
      return {potential, r == 0 ? 0.0 : (4.0 / 3 - 1.2 * q2 + 0.5 * q3) / h3};
    }
    const double potential = (4.0 / 3 * q2 - q3 + 0.3 * q2 * q2 - q2 * q3 / 30 - 1.6 + 1 / (15 * q)) / h;
    return {potential, (8.0 / 3 - 3 * q + 1.2 * q2 - q3 / 6 - 1 / (15 * q3)) / h3};
  }
};

/// Median and 99th percentile of `values` (reordered).
struct percentiles {
  double median = 0, p99 = 0, max = 0;
};
inline percentiles percentiles_of(std::vector<double> values) {
  percentiles result;
  if (values.empty()) return result;
  const auto at = [&](double fraction) {
    const std::size_t k = static_cast<std::size_t>(fraction * static_cast<double>(values.size() - 1));
    std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(k), values.end());
    return values[k];
  };
  result.median = at(0.5);
  result.p99 = at(0.99);
  result.max = *std::max_element(values.begin(), values.end());
  return result;
}

}  // namespace ntree_test
