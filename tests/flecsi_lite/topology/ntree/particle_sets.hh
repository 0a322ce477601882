// Particle sets for the ntree tests and benchmarks: uniform random, lattice, Gaussian blobs,
// Plummer sphere (Plummer 1911; sampling as Aarseth, Henon & Wielen 1974) and coincident points,
// with smoothing lengths from the known number density, sorted by (key, id) on request.
#pragma once

#include "flecsi_lite/topology/ntree/sfc/keys.hh"
#include "flecsi_lite/topology/ntree/sfc/ordering.hh"
#include "flecsi_lite/topology/ntree/space.hh"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <random>
#include <vector>

namespace ntree_test {

namespace nt = flecsi_lite::topology::ntree;

template<int D>
struct particle_set {
  std::vector<nt::point<D>> x;
  std::vector<double> m;
  std::vector<double> h;
  std::vector<std::uint64_t> id;
  std::vector<nt::key_type> keys;  // filled by sort_by_key
  nt::box<D> domain;               // the box keys are computed in

  std::size_t size() const { return x.size(); }
};

/// Volume of the unit ball in D dimensions.
template<int D>
constexpr double unit_ball_volume = D == 1   ? 2.0
                                    : D == 2 ? M_PI
                                             : 4.0 * M_PI / 3.0;

/// Smoothing length giving about `neighbours` particles within 2h at number density `density`.
template<int D>
double smoothing_length(double density, double neighbours) {
  return 0.5 * std::pow(neighbours / (unit_ball_volume<D> * density), 1.0 / D);
}

namespace detail {
template<int D>
void finish(particle_set<D>& set, const std::vector<double>& density, double neighbours, std::mt19937_64& random,
            double h_spread) {
  const std::size_t n = set.x.size();
  std::uniform_real_distribution<double> spread(1 - h_spread, 1 + h_spread);
  set.m.assign(n, 1.0 / static_cast<double>(n));
  set.h.resize(n);
  set.id.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    set.h[i] = smoothing_length<D>(density[i], neighbours) * spread(random);
    // Ids unrelated to positions, so that sorting by key really reorders them.
    set.id[i] = (static_cast<std::uint64_t>(i) * 0x9e3779b97f4a7c15ull) ^ 0x5bd1e995ull;
  }
  if (set.domain.is_empty()) {
    set.domain = nt::box<D>::empty();
    for (const auto& x : set.x) set.domain.extend(x);
    for (int k = 0; k < D; ++k) {
      const double pad = 1e-3 * (set.domain.hi[k] - set.domain.lo[k]) + 1e-12;
      set.domain.lo[k] -= pad;
      set.domain.hi[k] += pad;
    }
  }
}
}  // namespace detail

/// n points uniform in the unit box; h for about `neighbours` neighbours, times a random factor
/// in [1 - h_spread, 1 + h_spread].
template<int D>
particle_set<D> uniform(std::size_t n, std::uint64_t seed, double neighbours = 40, double h_spread = 0.3) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> unit(0, 1);
  particle_set<D> set;
  set.x.resize(n);
  for (auto& x : set.x)
    for (int k = 0; k < D; ++k) x[k] = unit(random);
  set.domain = nt::box<D>{};
  set.domain.lo.fill(0);
  set.domain.hi.fill(1);
  detail::finish(set, std::vector<double>(n, static_cast<double>(n)), neighbours, random, h_spread);
  return set;
}

/// A lattice of `per_axis`^D points at cell centres of the unit box, all with h = spacing
/// * h_over_spacing: many pair distances equal 2h exactly, testing the strict criterion.
template<int D>
particle_set<D> lattice(std::size_t per_axis, double h_over_spacing) {
  particle_set<D> set;
  std::size_t n = 1;
  for (int k = 0; k < D; ++k) n *= per_axis;
  const double spacing = 1.0 / static_cast<double>(per_axis);
  set.x.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    std::size_t rest = i;
    for (int k = 0; k < D; ++k, rest /= per_axis) set.x[i][k] = (static_cast<double>(rest % per_axis) + 0.5) * spacing;
  }
  set.domain.lo.fill(0);
  set.domain.hi.fill(1);
  std::mt19937_64 random(1);
  detail::finish(set, std::vector<double>(n, 1.0), 1.0, random, 0.0);
  for (auto& h : set.h) h = spacing * h_over_spacing;
  return set;
}

/// n points in `blobs` Gaussian clusters of width sigma (centres uniform in [0.25, 0.75]^D).
template<int D>
particle_set<D> gaussian_blobs(std::size_t n, std::size_t blobs, double sigma, std::uint64_t seed,
                               double neighbours = 40) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> centre(0.25, 0.75);
  std::normal_distribution<double> normal(0, sigma);
  std::vector<nt::point<D>> centres(blobs);
  for (auto& c : centres)
    for (int k = 0; k < D; ++k) c[k] = centre(random);
  particle_set<D> set;
  set.x.resize(n);
  for (std::size_t i = 0; i < n; ++i)
    for (int k = 0; k < D; ++k) set.x[i][k] = centres[i % blobs][k] + normal(random);
  // Number density: the sum of the blobs' Gaussians.
  std::vector<double> density(n, 0);
  const double norm = static_cast<double>(n) / static_cast<double>(blobs) / std::pow(2 * M_PI * sigma * sigma, 0.5 * D);
  for (std::size_t i = 0; i < n; ++i)
    for (const auto& c : centres)
      density[i] += norm * std::exp(-nt::distance_squared<D>(set.x[i], c) / (2 * sigma * sigma));
  set.domain = nt::box<D>::empty();
  detail::finish(set, density, neighbours, random, 0.1);
  return set;
}

/// A Plummer sphere of scale radius 1 (3D), truncated at 20 scale radii.
inline particle_set<3> plummer(std::size_t n, std::uint64_t seed, double neighbours = 40) {
  std::mt19937_64 random(seed);
  std::uniform_real_distribution<double> unit(0, 1);
  particle_set<3> set;
  set.x.resize(n);
  std::vector<double> density(n);
  for (std::size_t i = 0; i < n; ++i) {
    double r = 0;
    do {
      r = 1 / std::sqrt(std::pow(unit(random), -2.0 / 3.0) - 1);
    } while (!(r < 20));
    const double cos_theta = 2 * unit(random) - 1;
    const double sin_theta = std::sqrt(1 - cos_theta * cos_theta);
    const double phi = 2 * M_PI * unit(random);
    set.x[i] = {r * sin_theta * std::cos(phi), r * sin_theta * std::sin(phi), r * cos_theta};
    density[i] = static_cast<double>(n) * 3 / (4 * M_PI) * std::pow(1 + r * r, -2.5);
  }
  set.domain = nt::box<3>::empty();
  detail::finish(set, density, neighbours, random, 0.1);
  return set;
}

/// n uniform points of which most share positions: a quarter are distinct, the others copy one
/// of them, and the last `stack` all sit at one point (more than a bucket at the deepest level).
template<int D>
particle_set<D> coincident(std::size_t n, std::size_t stack, std::uint64_t seed, double neighbours = 40) {
  particle_set<D> set = uniform<D>(n, seed, neighbours, 0.3);
  std::mt19937_64 random(seed + 1);
  const std::size_t distinct = std::max<std::size_t>(1, n / 4);
  std::uniform_int_distribution<std::size_t> pick(0, distinct - 1);
  for (std::size_t i = distinct; i < n; ++i) set.x[i] = set.x[pick(random)];
  for (std::size_t i = n - std::min(stack, n); i < n; ++i) set.x[i] = set.x[0];
  return set;
}

/// Computes keys in set.domain, sorts every field by (key, id) and keeps the sorted keys.
template<int D>
void sort_by_key(particle_set<D>& set, nt::curve order) {
  const std::size_t n = set.size();
  std::vector<nt::key_type> keys(n);
  nt::compute_keys<D>(order, set.domain, set.x.data(), n, keys.data());
  const std::vector<std::size_t> permutation = nt::sort_permutation(keys.data(), set.id.data(), n);
  const auto permute = [&](auto& field) {
    auto sorted = field;
    nt::apply_permutation(permutation, field.data(), sorted.data());
    field.swap(sorted);
  };
  permute(set.x);
  permute(set.m);
  permute(set.h);
  permute(set.id);
  set.keys.resize(n);
  nt::apply_permutation(permutation, keys.data(), set.keys.data());
}

}  // namespace ntree_test
