// Tests of the hashed tree: node ranges partition the particles along the key hierarchy, leaves
// respect the bucket, hash lookups find every node, and the bottom-up moments (mass, centre,
// bounds, largest h, quadrupole) equal direct sums over each node's particles; the quadrupole,
// combined by parallel-axis shifts, is exactly symmetric with the trace of a traceless 3D tensor.
#include "flecsi_lite/topology/ntree/tree/hashed_tree.hh"
#include "tests/flecsi_lite/topology/ntree/particle_sets.hh"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

namespace nt = flecsi_lite::topology::ntree;

namespace {

template<int D>
void check_structure(const nt::hashed_tree<D>& tree, const ntree_test::particle_set<D>& set, std::size_t bucket) {
  const auto& nodes = tree.nodes();
  REQUIRE(tree.size() == set.size());
  REQUIRE(tree.root().key == nt::root_key);
  REQUIRE(tree.root().begin == 0);
  REQUIRE(tree.root().end == set.size());
  std::vector<int> covered(set.size(), 0);
  for (std::uint32_t i = 0; i < nodes.size(); ++i) {
    const auto& node = nodes[i];
    REQUIRE(tree.find(node.key) == i);
    REQUIRE(nt::level<D>(node.key) == node.level);
    REQUIRE(node.size() > 0);
    // Every particle of the node has the node's key as prefix, and no other particle does.
    for (std::uint32_t b = node.begin; b < node.end; ++b) REQUIRE(nt::ancestor<D>(set.keys[b], node.level) == node.key);
    if (node.begin > 0) REQUIRE(nt::ancestor<D>(set.keys[node.begin - 1], node.level) != node.key);
    if (node.end < set.size()) REQUIRE(nt::ancestor<D>(set.keys[node.end], node.level) != node.key);
    // The nodes of a level come in key order.
    if (i > 0 && nodes[i - 1].level == node.level) REQUIRE(nodes[i - 1].key < node.key);

    if (node.is_leaf()) {
      REQUIRE((node.size() <= bucket || node.level == nt::max_level<D>));
      for (std::uint32_t b = node.begin; b < node.end; ++b) ++covered[b];
      continue;
    }
    REQUIRE(node.size() > bucket);
    // Children: consecutive ranges that concatenate to the parent's range.
    std::uint32_t at = node.begin;
    for (std::uint32_t c = node.first_child; c < node.first_child + node.child_count; ++c) {
      REQUIRE(nt::parent<D>(nodes[c].key) == node.key);
      REQUIRE(nodes[c].begin == at);
      at = nodes[c].end;
    }
    REQUIRE(at == node.end);
  }
  // The leaves partition the particles.
  for (const int count : covered) REQUIRE(count == 1);
  // Keys of cells that hold no particle are not found.
  REQUIRE(tree.find(0) == tree.npos);
  REQUIRE(tree.find(nt::child<D>(nt::root_key, 0) << (D * nt::max_level<D>)) == tree.npos);
}

template<int D>
void check_moments(const nt::hashed_tree<D>& tree, const ntree_test::particle_set<D>& set) {
  for (std::uint32_t i = 0; i < tree.nodes().size(); ++i) {
    const auto& node = tree.node(i);
    nt::box<D> bounds = nt::box<D>::empty();
    double mass = 0, h_max = 0;
    nt::point<D> weighted{};
    for (std::uint32_t b = node.begin; b < node.end; ++b) {
      bounds.extend(set.x[b]);
      mass += set.m[b];
      h_max = std::max(h_max, set.h[b]);
      for (int k = 0; k < D; ++k) weighted[k] += set.m[b] * set.x[b][k];
    }
    REQUIRE(node.bounds == bounds);  // exact: min and max do not round
    REQUIRE(node.h_max == h_max);
    // The compact copy used by the searches is conservative: a wider box, a larger h.
    const auto& compact = tree.search_nodes()[i];
    for (int k = 0; k < D; ++k) {
      REQUIRE(static_cast<double>(compact.lo[k]) <= bounds.lo[k]);
      REQUIRE(static_cast<double>(compact.hi[k]) >= bounds.hi[k]);
    }
    REQUIRE(static_cast<double>(compact.h_max) >= h_max);
    REQUIRE(compact.begin == node.begin);
    REQUIRE(compact.end == node.end);
    REQUIRE(compact.first_child == node.first_child);
    REQUIRE(compact.child_count == node.child_count);
    REQUIRE(node.mass == Approx(mass).epsilon(1e-13));
    nt::point<D> centre;
    for (int k = 0; k < D; ++k) centre[k] = weighted[k] / mass;
    const double scale = std::max(1.0, tree.root().bounds.max_extent());
    for (int k = 0; k < D; ++k) REQUIRE(std::abs(node.centre[k] - centre[k]) <= 1e-13 * scale);

    if (!tree.has_quadrupoles()) continue;
    // The direct sum about the node's centre of mass, and the moment of inertia sum m |d|^2.
    nt::quadrupole<D> q = nt::quadrupole<D>::Zero();
    double inertia = 0;
    for (std::uint32_t b = node.begin; b < node.end; ++b) {
      const nt::column_vector<D> d = nt::as_column_vector<D>(set.x[b]) - nt::as_column_vector<D>(centre);
      nt::add_point_mass<D>(q, set.m[b], d);
      inertia += set.m[b] * d.squaredNorm();
    }
    // Scale of the quadrupole: mass times the squared size of the node.
    const double size = node.bounds.max_extent();
    const double q_scale = mass * size * size + 1e-300;
    const nt::quadrupole<D>& tree_q = tree.node_quadrupole(i);
    REQUIRE((tree_q - q).cwiseAbs().maxCoeff() <= 1e-11 * q_scale);
    // Exactly symmetric, and the D x D block of a traceless 3D tensor: trace (3 - D) sum m |d|^2,
    // to rounding of the inertia itself where the node has no extent (one particle, coincident).
    REQUIRE(tree_q == tree_q.transpose());
    REQUIRE(std::abs(tree_q.trace() - (3 - D) * inertia) <= 1e-11 * q_scale + 1e-12 * inertia);
  }
}

template<int D>
void check_set(ntree_test::particle_set<D> set, std::size_t bucket) {
  for (const nt::curve order : {nt::curve::morton, nt::curve::hilbert}) {
    ntree_test::sort_by_key(set, order);
    nt::hashed_tree<D> tree;
    tree.build(set.keys.data(), set.x.data(), set.m.data(), set.h.data(), set.size(), {bucket, true});
    check_structure(tree, set, bucket);
    check_moments(tree, set);
  }
}

}  // namespace

TEST_CASE("hashed tree of uniform, lattice and clustered particles", "[ntree][tree]") {
  check_set(ntree_test::uniform<1>(2000, 1), 8);
  check_set(ntree_test::uniform<2>(3000, 2), 16);
  check_set(ntree_test::uniform<3>(3000, 3), 16);
  check_set(ntree_test::lattice<2>(40, 1.0), 16);
  check_set(ntree_test::lattice<3>(14, 1.0), 4);
  check_set(ntree_test::gaussian_blobs<2>(3000, 3, 0.01, 4), 16);
  check_set(ntree_test::gaussian_blobs<3>(3000, 4, 0.02, 5), 16);
  check_set(ntree_test::plummer(3000, 6), 16);
}

TEST_CASE("coincident particles: a deepest-level leaf holds them all", "[ntree][tree]") {
  for (const std::size_t bucket : {1, 16}) {
    check_set(ntree_test::coincident<1>(1000, 50, 7), bucket);
    check_set(ntree_test::coincident<2>(1000, 50, 8), bucket);
    check_set(ntree_test::coincident<3>(2000, 100, 9), bucket);
  }
  // All particles at one point: one chain of single children down to a deepest leaf.
  auto set = ntree_test::coincident<3>(64, 64, 10);
  ntree_test::sort_by_key(set, nt::curve::hilbert);
  nt::hashed_tree<3> tree;
  tree.build(set.keys.data(), set.x.data(), set.m.data(), set.h.data(), set.size(), {16, false});
  REQUIRE(tree.depth() == nt::max_level<3>);
  REQUIRE(tree.nodes().size() == nt::max_level<3> + 1);
  REQUIRE(tree.nodes().back().size() == 64);
}

TEST_CASE("tiny trees: no particle, one particle", "[ntree][tree]") {
  nt::hashed_tree<2> tree;
  tree.build(nullptr, nullptr, nullptr, nullptr, 0);
  REQUIRE(tree.size() == 0);
  REQUIRE(tree.nodes().size() == 1);
  REQUIRE(tree.root().is_leaf());
  REQUIRE(tree.depth() == 0);

  auto set = ntree_test::uniform<2>(1, 3);
  ntree_test::sort_by_key(set, nt::curve::morton);
  tree.build(set.keys.data(), set.x.data(), set.m.data(), set.h.data(), 1);
  REQUIRE(tree.nodes().size() == 1);
  REQUIRE(tree.root().centre == set.x[0]);
  REQUIRE(tree.root().mass == set.m[0]);
}

TEST_CASE("refit follows moved particles with the same structure", "[ntree][tree]") {
  auto set = ntree_test::uniform<3>(2000, 12);
  ntree_test::sort_by_key(set, nt::curve::hilbert);
  nt::hashed_tree<3> tree;
  tree.build(set.keys.data(), set.x.data(), set.m.data(), set.h.data(), set.size(), {16, true});
  const std::size_t node_count = tree.nodes().size();
  for (std::size_t i = 0; i < set.size(); ++i) {
    set.x[i][0] += 0.01 * std::sin(7.0 * static_cast<double>(i));
    set.m[i] *= 1.5;
    set.h[i] *= 0.9;
  }
  tree.refit(set.x.data(), set.m.data(), set.h.data());
  REQUIRE(tree.nodes().size() == node_count);
  check_moments(tree, set);
}

// With individual time steps the local tree's refresh recomputes only the nodes holding a
// particle that changed (hashed_tree::refit_moved; local_tree::refresh finds them): the nodes
// must be bit for bit those of a whole refit, or the searches (and the outputs) would change.
TEST_CASE("a refit of the moved particles' nodes equals a whole refit bit for bit", "[ntree][tree]") {
  const auto same = [](double a, double b) { return std::memcmp(&a, &b, sizeof(double)) == 0; };
  const auto same_points = [&](const nt::point<3>& a, const nt::point<3>& b) {
    return same(a[0], b[0]) && same(a[1], b[1]) && same(a[2], b[2]);
  };
  for (const bool quadrupole : {false, true}) {
    auto set = ntree_test::gaussian_blobs<3>(4000, 3, 0.05, 15);
    ntree_test::sort_by_key(set, nt::curve::hilbert);
    nt::hashed_tree<3> whole, partial;  // both read the set's arrays
    whole.build(set.keys.data(), set.x.data(), set.m.data(), set.h.data(), set.size(), {16, quadrupole});
    partial.build(set.keys.data(), set.x.data(), set.m.data(), set.h.data(), set.size(), {16, quadrupole});
    std::mt19937_64 random(16);
    std::uniform_real_distribution<double> jitter(-0.02, 0.02);
    // Rounds that move a twentieth of the particles (x, m or h alone), none, or all of them.
    for (const std::size_t every : {20, 20, 1000000, 1}) {
      std::vector<std::uint8_t> moved(set.size(), 0);
      for (std::size_t b = 0; b < set.size(); ++b) {
        if (random() % every != 0) continue;
        moved[b] = 1;
        switch (random() % 3) {
          case 0:
            set.x[b][random() % 3] += jitter(random);
            break;
          case 1:
            set.m[b] *= 1.5;
            break;
          default:
            set.h[b] *= 1 + jitter(random);
            break;
        }
      }
      whole.refit(set.x.data(), set.m.data(), set.h.data());
      partial.refit_moved(set.x.data(), set.m.data(), set.h.data(), moved.data());
      for (std::uint32_t i = 0; i < whole.nodes().size(); ++i) {
        const auto &a = whole.node(i), &b = partial.node(i);
        REQUIRE(same_points(a.bounds.lo, b.bounds.lo));
        REQUIRE(same_points(a.bounds.hi, b.bounds.hi));
        REQUIRE(same_points(a.centre, b.centre));
        REQUIRE(same(a.h_max, b.h_max));
        REQUIRE(same(a.mass, b.mass));
        const auto &c = whole.search_nodes()[i], &d = partial.search_nodes()[i];
        REQUIRE(std::memcmp(c.lo.data(), d.lo.data(), sizeof(c.lo)) == 0);
        REQUIRE(std::memcmp(c.hi.data(), d.hi.data(), sizeof(c.hi)) == 0);
        REQUIRE(std::memcmp(&c.h_max, &d.h_max, sizeof(c.h_max)) == 0);
        if (quadrupole) REQUIRE(whole.node_quadrupole(i) == partial.node_quadrupole(i));
      }
      check_moments(partial, set);
    }
  }
}

TEST_CASE("tree memory is a few tens of bytes per particle", "[ntree][tree]") {
  auto set = ntree_test::uniform<3>(4000, 13);
  ntree_test::sort_by_key(set, nt::curve::hilbert);
  nt::hashed_tree<3> tree;
  tree.build(set.keys.data(), set.x.data(), set.m.data(), set.h.data(), set.size());
  REQUIRE(tree.bytes() >= tree.nodes().size() * sizeof(nt::tree_node<3>));
  REQUIRE(tree.bytes() < 64 * set.size());
}

TEST_CASE("outward rounding to float never moves a bound inward", "[ntree][tree]") {
  std::mt19937_64 random(14);
  std::uniform_real_distribution<double> mantissa(-1, 1);
  for (int trial = 0; trial < 10000; ++trial) {
    const double value = std::ldexp(mantissa(random), static_cast<int>(random() % 80) - 40);
    const float below = nt::float_below(value);
    const float above = nt::float_above(value);
    REQUIRE(static_cast<double>(below) <= value);
    REQUIRE(static_cast<double>(above) >= value);
    // Tight: the next float outward would overshoot by more than one float step.
    REQUIRE(std::nextafter(below, 1e30f) >= value);
    REQUIRE(std::nextafter(above, -1e30f) <= value);
  }
  REQUIRE(nt::float_below(0.1) < 0.1f);  // the nearest float, 0.1f, lies above 0.1
  REQUIRE(nt::float_above(1e300) == std::numeric_limits<float>::infinity());
}
