// Tests of the Barnes-Hut walk: accepted nodes and particles partition the sources, theta = 0
// gives the direct sum exactly, and the monopole + quadrupole force converges to the direct sum
// as theta shrinks, the quadrupole beating the monopole alone.
#include "flecsi_lite/topology/ntree/barnes_hut.hh"
#include "tests/flecsi_lite/topology/ntree/particle_sets.hh"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

namespace nt = flecsi_lite::topology::ntree;
using namespace ntree_test;

namespace {

struct fixture {
  particle_set<3> set;
  nt::hashed_tree<3> tree;

  explicit fixture(std::size_t bucket) : set(plummer(2000, 41)) {
    sort_by_key(set, nt::curve::hilbert);
    tree.build(set.keys.data(), set.x.data(), set.m.data(), set.h.data(), set.size(),
               {bucket, true});
  }
};

// Direct-sum acceleration on particle a (G = 1, no softening), in ascending source order.
nt::point<3> direct(const particle_set<3>& set, std::size_t a,
                    const std::vector<std::uint32_t>& sources) {
  nt::point<3> acceleration{};
  for (const std::uint32_t b : sources) {
    if (b == a) continue;
    nt::point<3> d;
    for (int k = 0; k < 3; ++k) d[k] = set.x[b][k] - set.x[a][k];
    const double r2 = nt::distance_squared<3>(set.x[a], set.x[b]);
    const double inverse_r3 = 1 / (r2 * std::sqrt(r2));
    for (int k = 0; k < 3; ++k) acceleration[k] += set.m[b] * d[k] * inverse_r3;
  }
  return acceleration;
}

nt::point<3> tree_acceleration(const fixture& f, std::size_t a, const nt::interaction_list& list,
                               bool quadrupole) {
  nt::point<3> acceleration = direct(f.set, a, list.particles);
  const nt::quadrupole<3> none{};
  for (const std::uint32_t i : list.nodes) {
    const auto& node = f.tree.node(i);
    const auto field = nt::multipole_acceleration<3>(
      node.mass, node.center, quadrupole ? f.tree.node_quadrupole(i) : none, f.set.x[a]);
    for (int k = 0; k < 3; ++k) acceleration[k] += field[k];
  }
  return acceleration;
}

double norm(const nt::point<3>& v) { return std::sqrt(v[0] * v[0] + v[1] * v[1] + v[2] * v[2]); }

// RMS over particles of |a_tree - a_direct| / |a_direct|.
double rms_error(const fixture& f, double theta, bool quadrupole) {
  std::vector<std::uint32_t> all(f.set.size());
  for (std::uint32_t b = 0; b < all.size(); ++b) all[b] = b;
  nt::interaction_list list;
  double sum = 0;
  std::size_t count = 0;
  for (std::size_t a = 0; a < f.set.size(); a += 4) {
    nt::barnes_hut_walk<3>(f.tree, f.set.x[a], theta, list);
    const auto exact = direct(f.set, a, all);
    const auto approximate = tree_acceleration(f, a, list, quadrupole);
    nt::point<3> error;
    for (int k = 0; k < 3; ++k) error[k] = approximate[k] - exact[k];
    const double relative = norm(error) / norm(exact);
    sum += relative * relative;
    ++count;
  }
  return std::sqrt(sum / static_cast<double>(count));
}

// Every source is in exactly one accepted node or in the particle list.
void check_partition(const nt::hashed_tree<3>& tree, const nt::interaction_list& list) {
  std::vector<int> seen(tree.size(), 0);
  for (const std::uint32_t i : list.nodes)
    for (std::uint32_t b = tree.node(i).begin; b < tree.node(i).end; ++b) ++seen[b];
  for (const std::uint32_t b : list.particles) ++seen[b];
  for (const int count : seen) REQUIRE(count == 1);
  REQUIRE(std::is_sorted(list.particles.begin(), list.particles.end()));
}

} // namespace

TEST_CASE("theta = 0 opens every node: the list is all particles", "[ntree][barnes_hut]") {
  const fixture f(8);
  nt::interaction_list list;
  for (const std::size_t a : {0, 500, 1999}) {
    nt::barnes_hut_walk<3>(f.tree, f.set.x[a], 0.0, list);
    REQUIRE(list.nodes.empty());
    REQUIRE(list.particles.size() == f.set.size());
    check_partition(f.tree, list);
    std::vector<std::uint32_t> all(f.set.size());
    for (std::uint32_t b = 0; b < all.size(); ++b) all[b] = b;
    REQUIRE(tree_acceleration(f, a, list, true) == direct(f.set, a, all)); // bitwise
  }
}

TEST_CASE("accepted nodes satisfy the criterion and partition the sources",
          "[ntree][barnes_hut]") {
  const fixture f(8);
  nt::interaction_list list;
  for (const double theta : {0.3, 0.7, 1.2}) {
    for (std::size_t a = 0; a < f.set.size(); a += 97) {
      nt::barnes_hut_walk<3>(f.tree, f.set.x[a], theta, list);
      check_partition(f.tree, list);
      REQUIRE(!list.nodes.empty());
      for (const std::uint32_t i : list.nodes) {
        const auto& node = f.tree.node(i);
        REQUIRE_FALSE(node.bounds.contains(f.set.x[a]));
        const double distance = std::sqrt(nt::distance_squared<3>(f.set.x[a], node.center));
        REQUIRE(node.bounds.max_extent() < theta * distance);
      }
    }
    // A group of targets: the criterion holds for every point of the group's box.
    const auto& group = f.tree.node(f.tree.level_begin(3));
    nt::barnes_hut_walk<3>(f.tree, group.bounds, theta, list);
    check_partition(f.tree, list);
    for (const std::uint32_t i : list.nodes) {
      const auto& node = f.tree.node(i);
      REQUIRE_FALSE(node.bounds.intersects(group.bounds));
      for (std::uint32_t a = group.begin; a < group.end; ++a) {
        const double distance = std::sqrt(nt::distance_squared<3>(f.set.x[a], node.center));
        REQUIRE(node.bounds.max_extent() < theta * distance);
      }
    }
  }
}

TEST_CASE("monopole + quadrupole force converges to the direct sum", "[ntree][barnes_hut]") {
  const fixture f(8);
  // RMS relative errors of a quadrupole tree code scale about as theta^4 (measured here:
  // 1.3e-4, 2.1e-3, 1.6e-2 at theta 0.25, 0.5, 0.75); the bounds leave a factor ~2.
  const std::pair<double, double> bounds[] = {{0.25, 3e-4}, {0.5, 5e-3}, {0.75, 3e-2},
                                              {1.0, 8e-2}};
  double previous = 0;
  for (const auto& [theta, bound] : bounds) {
    const double with_quadrupole = rms_error(f, theta, true);
    const double monopole_only = rms_error(f, theta, false);
    INFO("theta " << theta << ": quadrupole " << with_quadrupole << ", monopole "
                  << monopole_only);
    REQUIRE(with_quadrupole < monopole_only);
    REQUIRE(with_quadrupole > previous); // the error shrinks with theta
    REQUIRE(with_quadrupole < bound);
    previous = with_quadrupole;
  }
}

TEST_CASE("multipole field of two masses matches its expansion", "[ntree][barnes_hut]") {
  // Masses m at +-d on z, seen from z on the axis: a_z = -2m/z^2 - 6 m d^2 / z^4 + O(d^4/z^6).
  const double m = 0.5, d = 0.01, z = 1.0;
  nt::quadrupole<3> q{};
  nt::add_point_mass<3>(q, m, {0, 0, d});
  nt::add_point_mass<3>(q, m, {0, 0, -d});
  const auto a = nt::multipole_acceleration<3>(2 * m, {0, 0, 0}, q, {0, 0, z});
  REQUIRE(a[0] == 0);
  REQUIRE(a[1] == 0);
  const double exact = -m / ((z - d) * (z - d)) - m / ((z + d) * (z + d));
  REQUIRE(std::abs(a[2] - exact) < 20 * m * std::pow(d / z, 4));
  REQUIRE(nt::multipole_potential<3>(2 * m, {0, 0, 0}, q, {0, 0, z}) ==
          Approx(-m / (z - d) - m / (z + d)).epsilon(1e-7));
}
