// Tests of the local tree's refresh: it recomputes only the nodes of particles whose values
// changed (bit for bit); the nodes must then equal those of a tree built anew from the same
// values, or a search after the refresh would miss neighbours.
#include "flecsi_lite/topology/ntree/tree/local_tree.hh"
#include "tests/flecsi_lite/topology/ntree/particle_sets.hh"

#include <catch2/catch.hpp>

#include <cstring>
#include <random>
#include <vector>

namespace nt = flecsi_lite::topology::ntree;

namespace {

nt::local_tree<3> build(const ntree_test::particle_set<3>& set) {
  nt::local_tree<3> tree;
  tree.build(set.keys.data(), set.id.data(), set.x.data(), set.m.data(), set.h.data(), set.size(), set.size(), {0},
             nt::tree_options{8, false});
  return tree;
}

void require_same_nodes(const nt::local_tree<3>& a, const nt::local_tree<3>& b) {
  const auto& left = a.tree().search_nodes();
  const auto& right = b.tree().search_nodes();
  REQUIRE(left.size() == right.size());
  for (std::size_t i = 0; i < left.size(); ++i) {
    REQUIRE(std::memcmp(left[i].lo.data(), right[i].lo.data(), sizeof(left[i].lo)) == 0);
    REQUIRE(std::memcmp(left[i].hi.data(), right[i].hi.data(), sizeof(left[i].hi)) == 0);
    REQUIRE(left[i].h_max == right[i].h_max);
    REQUIRE(a.tree().node(i).mass == b.tree().node(i).mass);
    REQUIRE(a.tree().node(i).h_max == b.tree().node(i).h_max);
  }
}

}  // namespace

TEST_CASE("a refresh equals a new build after moves, changes of h and none", "[ntree][local_tree]") {
  auto set = ntree_test::uniform<3>(3000, 51);
  ntree_test::sort_by_key(set, nt::curve::hilbert);
  nt::local_tree<3> tree = build(set);
  std::mt19937_64 random(52);
  std::uniform_real_distribution<double> jitter(-0.01, 0.01);

  // A tenth of the particles move or change h.
  for (std::size_t a = 0; a < set.size(); a += 10) {
    set.x[a][a % 3] += jitter(random);
    set.h[a] *= 1.3;
  }
  tree.refresh(set.x.data(), set.m.data(), set.h.data());
  require_same_nodes(tree, build(set));

  // Only h changes, of a few particles: their nodes' largest h must follow.
  for (std::size_t a = 3; a < set.size(); a += 50) set.h[a] *= 2;
  tree.refresh(set.x.data(), set.m.data(), set.h.data());
  require_same_nodes(tree, build(set));

  // Nothing changed; then every particle moves.
  tree.refresh(set.x.data(), set.m.data(), set.h.data());
  require_same_nodes(tree, build(set));
  for (auto& x : set.x) x[1] += 1e-4;
  tree.refresh(set.x.data(), set.m.data(), set.h.data());
  require_same_nodes(tree, build(set));
}
