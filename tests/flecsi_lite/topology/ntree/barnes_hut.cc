// Tests of the Barnes-Hut walk and the multipole field: accepted nodes and particles partition
// the sources, theta = 0 gives the direct sum exactly, the monopole + quadrupole force converges
// to the direct sum as theta shrinks (the quadrupole beating the monopole alone), and the
// acceleration is minus the gradient of the potential.
#include "flecsi_lite/topology/ntree/gravity/barnes_hut.hh"
#include "tests/flecsi_lite/topology/ntree/particle_sets.hh"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <random>
#include <vector>

namespace nt = flecsi_lite::topology::ntree;
using namespace ntree_test;

namespace {

using vector3 = nt::column_vector<3>;

struct fixture {
  particle_set<3> set;
  nt::hashed_tree<3> tree;

  explicit fixture(std::size_t bucket) : set(plummer(2000, 41)) {
    sort_by_key(set, nt::curve::hilbert);
    tree.build(set.keys.data(), set.x.data(), set.m.data(), set.h.data(), set.size(), {bucket, true});
  }
};

// Direct-sum acceleration on particle a (G = 1, no softening), in ascending source order.
vector3 direct(const particle_set<3>& set, std::size_t a, const std::vector<std::uint32_t>& sources) {
  vector3 acceleration = vector3::Zero();
  for (const std::uint32_t b : sources) {
    if (b == a) continue;
    const vector3 d = nt::as_column_vector<3>(set.x[b]) - nt::as_column_vector<3>(set.x[a]);
    const double r2 = d.squaredNorm();
    acceleration += set.m[b] / (r2 * std::sqrt(r2)) * d;
  }
  return acceleration;
}

vector3 tree_acceleration(const fixture& f, std::size_t a, const nt::interaction_list& list, bool quadrupole) {
  vector3 acceleration = direct(f.set, a, list.particles);
  const nt::quadrupole<3> none = nt::quadrupole<3>::Zero();
  for (const std::uint32_t i : list.nodes) {
    const auto& node = f.tree.node(i);
    acceleration += nt::as_column_vector<3>(
      nt::multipole_acceleration<3>(node.mass, node.centre, quadrupole ? f.tree.node_quadrupole(i) : none, f.set.x[a]));
  }
  return acceleration;
}

// RMS over particles of |a_tree - a_direct| / |a_direct|.
double rms_error(const fixture& f, double theta, bool quadrupole) {
  std::vector<std::uint32_t> all(f.set.size());
  for (std::uint32_t b = 0; b < all.size(); ++b) all[b] = b;
  nt::interaction_list list;
  double sum = 0;
  std::size_t count = 0;
  for (std::size_t a = 0; a < f.set.size(); a += 4) {
    nt::barnes_hut_walk<3>(f.tree, f.set.x[a], theta, list);
    const vector3 exact = direct(f.set, a, all);
    const double relative = (tree_acceleration(f, a, list, quadrupole) - exact).norm() / exact.norm();
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

}  // namespace

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
    REQUIRE(tree_acceleration(f, a, list, true) == direct(f.set, a, all));  // bitwise
  }
}

TEST_CASE("accepted nodes satisfy the criterion and partition the sources", "[ntree][barnes_hut]") {
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
        const double distance = std::sqrt(nt::distance_squared<3>(f.set.x[a], node.centre));
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
        const double distance = std::sqrt(nt::distance_squared<3>(f.set.x[a], node.centre));
        REQUIRE(node.bounds.max_extent() < theta * distance);
      }
    }
  }
}

TEST_CASE("monopole + quadrupole force converges to the direct sum", "[ntree][barnes_hut]") {
  const fixture f(8);
  // RMS relative errors of a quadrupole tree code scale about as theta^4 (measured here:
  // 1.3e-4, 2.1e-3, 1.6e-2 at theta 0.25, 0.5, 0.75); the bounds leave a factor ~2.
  const std::pair<double, double> bounds[] = {{0.25, 3e-4}, {0.5, 5e-3}, {0.75, 3e-2}, {1.0, 8e-2}};
  double previous = 0;
  for (const auto& [theta, bound] : bounds) {
    const double with_quadrupole = rms_error(f, theta, true);
    const double monopole_only = rms_error(f, theta, false);
    INFO("theta " << theta << ": quadrupole " << with_quadrupole << ", monopole " << monopole_only);
    REQUIRE(with_quadrupole < monopole_only);
    REQUIRE(with_quadrupole > previous);  // the error shrinks with theta
    REQUIRE(with_quadrupole < bound);
    previous = with_quadrupole;
  }
}

TEST_CASE("multipole field of two masses matches its expansion", "[ntree][barnes_hut]") {
  // Masses m at +-d on z, seen from z on the axis: a_z = -2m/z^2 - 6 m d^2 / z^4 + O(d^4/z^6).
  const double m = 0.5, d = 0.01, z = 1.0;
  nt::quadrupole<3> q = nt::quadrupole<3>::Zero();
  nt::add_point_mass<3>(q, m, vector3(0, 0, d));
  nt::add_point_mass<3>(q, m, vector3(0, 0, -d));
  const auto a = nt::multipole_acceleration<3>(2 * m, {0, 0, 0}, q, {0, 0, z});
  REQUIRE(a[0] == 0);
  REQUIRE(a[1] == 0);
  const double exact = -m / ((z - d) * (z - d)) - m / ((z + d) * (z + d));
  REQUIRE(std::abs(a[2] - exact) < 20 * m * std::pow(d / z, 4));
  REQUIRE(nt::multipole_potential<3>(2 * m, {0, 0, 0}, q, {0, 0, z}) ==
          Approx(-m / (z - d) - m / (z + d)).epsilon(1e-7));
}

TEST_CASE("multipole acceleration is minus the gradient of its potential", "[ntree][barnes_hut]") {
  // A lopsided cluster (no symmetry to hide a wrong term) seen from points at a few radii.
  std::mt19937_64 random(43);
  std::uniform_real_distribution<double> unit(-1, 1);
  double mass = 0;
  vector3 weighted = vector3::Zero();
  std::vector<std::pair<double, vector3>> masses;
  for (int b = 0; b < 20; ++b) {
    const vector3 x(0.3 * unit(random), 0.1 * unit(random), 0.05 * unit(random) + 0.02 * b / 20.0);
    const double m = 1 + 0.5 * unit(random);
    masses.emplace_back(m, x);
    mass += m;
    weighted += m * x;
  }
  const vector3 centre_of_mass = weighted / mass;
  nt::quadrupole<3> q = nt::quadrupole<3>::Zero();
  for (const auto& [m, x] : masses) nt::add_point_mass<3>(q, m, x - centre_of_mass);
  REQUIRE(q == q.transpose());                                      // exactly symmetric
  REQUIRE(std::abs(q.trace()) <= 1e-14 * q.cwiseAbs().maxCoeff());  // traceless in 3D
  REQUIRE(q.cwiseAbs().maxCoeff() > 0.01 * mass * 0.3 * 0.3);       // and not zero

  nt::point<3> centre;
  nt::as_column_vector<3>(centre) = centre_of_mass;
  const double step = 1e-5;
  for (int trial = 0; trial < 20; ++trial) {
    const vector3 direction = vector3(unit(random), unit(random), unit(random)).normalized();
    nt::point<3> x;
    nt::as_column_vector<3>(x) = centre_of_mass + (1.5 + trial * 0.25) * direction;
    const auto acceleration = nt::multipole_acceleration<3>(mass, centre, q, x);
    for (int k = 0; k < 3; ++k) {
      nt::point<3> forward = x, backward = x;
      forward[k] += step;
      backward[k] -= step;
      const double gradient =
        (nt::multipole_potential<3>(mass, centre, q, forward) - nt::multipole_potential<3>(mass, centre, q, backward)) /
        (2 * step);
      // Central differences: error ~ step^2 |phi'''| plus rounding ~ 1e-16 |phi| / step.
      REQUIRE(std::abs(acceleration[k] + gradient) <= 1e-8 * nt::as_column_vector<3>(acceleration).norm());
    }
  }
}
