// Tests of the two-step group walk (seed Algorithm 2): groups partition the particles, and the
// neighbours found through the per-group interaction lists equal the brute-force ones exactly
// and in ascending order, for gather and symmetric searches, any group size or mass, some
// targets only, by callback and as CSR lists.
#include "flecsi_lite/topology/ntree/search/group_walk.hh"
#include "flecsi_lite/topology/ntree/search/radius_search.hh"
#include "tests/flecsi_lite/topology/ntree/search_checks.hh"

#include <catch2/catch.hpp>

#include <random>
#include <vector>

namespace nt = flecsi_lite::topology::ntree;
using namespace ntree_test;

namespace {

template<int D>
void check_groups_partition(const nt::group_walk<D>& walk, const nt::hashed_tree<D>& tree,
                            const nt::group_options& grouping) {
  std::uint32_t at = 0;
  for (const std::uint32_t g : walk.groups()) {
    const auto& node = tree.node(g);
    REQUIRE(node.begin == at);
    at = node.end;
    const bool small =
      node.size() <= grouping.max_group_size || (grouping.max_group_mass > 0 && node.mass <= grouping.max_group_mass);
    const bool compact =
      grouping.max_group_extent <= 0 || node.bounds.max_extent() <= grouping.max_group_extent * 2.0 * node.h_max;
    REQUIRE((node.is_leaf() || (small && compact)));
  }
  REQUIRE(at == tree.size());
}

template<int D>
void check_group_walk(nt::curve order) {
  const auto space = nt::domain<D>::open();
  for (const auto& set : search_sets<D>(order)) {
    const auto tree = build_tree(set, 8);
    const auto mask = random_targets(set.size(), 23);
    const double total_mass = tree.root().mass;
    const nt::group_options groupings[] = {
      {1, 0, 0},     {8, 0, 0}, {64, 0, 0}, {64, 0, 0.5}, {100000, 0.02 * total_mass, 0},
      {32, 0, 0, 40}};  // the last: most groups fall back to per-target walks
    for (const nt::interaction kind : {nt::interaction::gather, nt::interaction::symmetric}) {
      for (const std::uint8_t* targets : {static_cast<const std::uint8_t*>(nullptr), mask.data()}) {
        const nt::search_options options{kind, 2.0, targets};
        const auto expected = brute_force(set, space, options);
        for (const auto& grouping : groupings) {
          nt::group_walk<D> walk(options, grouping);
          nt::neighbour_lists found;
          walk.find_neighbours(tree, space, found);
          require_equal(found, expected);
          check_groups_partition(walk, tree, grouping);
          REQUIRE(walk.interaction_list_entries() >= expected.total() / set.size());
          // The callback path shares the walk; checking it for two groupings is enough.
          if (grouping.max_group_size == 8 || grouping.max_list_length < 100)
            require_equal(lists_from_callback(walk, tree, space), expected);
        }
      }
    }
  }
}

}  // namespace

TEST_CASE("group walk equals brute force in 1D", "[ntree][group_walk]") { check_group_walk<1>(nt::curve::hilbert); }

TEST_CASE("group walk equals brute force in 2D", "[ntree][group_walk]") {
  check_group_walk<2>(nt::curve::hilbert);
  check_group_walk<2>(nt::curve::morton);
}

TEST_CASE("group walk equals brute force in 3D", "[ntree][group_walk]") { check_group_walk<3>(nt::curve::hilbert); }

TEST_CASE("group walk on a Plummer sphere with adaptive h", "[ntree][group_walk]") {
  auto set = plummer(3000, 31, 60);
  sort_by_key(set, nt::curve::hilbert);
  const auto tree = build_tree(set, 16);
  const auto space = nt::domain<3>::open();
  for (const nt::interaction kind : {nt::interaction::gather, nt::interaction::symmetric}) {
    const nt::search_options options{kind, 2.0, nullptr};
    nt::group_walk<3> walk(options, {32, 0});
    nt::neighbour_lists found;
    walk.find_neighbours(tree, space, found);
    require_equal(found, brute_force(set, space, options));
    // A reused walk object (warm workspaces) gives the same answer.
    nt::neighbour_lists again;
    walk.find_neighbours(tree, space, again);
    require_equal(again, found);
  }
}

// A walk from targets whose h changed after the build, without a refit: a symmetric search from
// those targets, grouped or one by one, must find, among the particles whose h did not change,
// what it finds after a refit (the brute force with the new h), though the nodes' largest h are
// stale, lower where a target's h grew and higher where it shrank. (The time-step limiter's
// wake-up from ghost sources searched so until stop 49; docs/performance.md.)
TEST_CASE("a search from targets whose h changed after the build is exact for the unchanged particles",
          "[ntree][group_walk]") {
  const auto space = nt::domain<3>::open();
  for (auto set : {uniform<3>(3000, 41), gaussian_blobs<3>(3000, 3, 0.02, 43)}) {
    sort_by_key(set, nt::curve::hilbert);
    const auto tree = build_tree(set, 16);  // keeps pointers to set.x and set.h
    std::mt19937_64 random(47);
    std::uniform_real_distribution<double> factor(0.5, 2.0);
    std::vector<std::uint8_t> changed(set.size());
    for (std::size_t a = 0; a < set.size(); ++a)
      if (random() % 10 == 0) {
        changed[a] = 1;
        set.h[a] *= factor(random);
      }
    const nt::search_options options{nt::interaction::symmetric, 2.0, changed.data()};
    const auto expected = brute_force(set, space, options);
    const auto require_unchanged_equal = [&](const nt::neighbour_lists& found) {
      REQUIRE(found.size() == expected.size());
      std::size_t compared = 0;
      for (std::size_t a = 0; a < set.size(); ++a) {
        std::vector<std::uint32_t> unchanged_found, unchanged_expected;
        for (std::size_t j = found.offsets[a]; j < found.offsets[a + 1]; ++j)
          if (!changed[found.neighbours[j]]) unchanged_found.push_back(found.neighbours[j]);
        for (std::size_t j = expected.offsets[a]; j < expected.offsets[a + 1]; ++j)
          if (!changed[expected.neighbours[j]]) unchanged_expected.push_back(expected.neighbours[j]);
        REQUIRE(unchanged_found == unchanged_expected);
        compared += unchanged_expected.size();
      }
      REQUIRE(compared > set.size());  // about 40 neighbours for each of a tenth of the particles
    };
    nt::radius_search<3> per_target(options);
    require_unchanged_equal(lists_from_callback(per_target, tree, space));
    for (const std::size_t group_size : {std::size_t(1), std::size_t(32)}) {
      nt::group_walk<3> walk(options, {group_size, 0});
      nt::neighbour_lists found;
      walk.find_neighbours(tree, space, found);
      require_unchanged_equal(found);
    }
  }
}

// A walk keeps its groups while its tree keeps its structure (hashed_tree::build_id): after a
// refit of moved particles it must still equal the brute force, and after a new build of the
// same tree object (other particles, other nodes) find new groups.
TEST_CASE("a walk kept over refits and rebuilds of its tree equals brute force", "[ntree][group_walk]") {
  const auto space = nt::domain<3>::open();
  auto set = uniform<3>(3000, 61);
  sort_by_key(set, nt::curve::hilbert);
  auto tree = build_tree(set, 8);
  const nt::search_options options{nt::interaction::symmetric, 2.0, nullptr};
  const nt::group_options grouping{32, 0, 0};
  nt::group_walk<3> walk(options, grouping);
  const auto search_equals_brute_force = [&]() {
    nt::neighbour_lists found;
    walk.find_neighbours(tree, space, found);
    require_equal(found, brute_force(set, space, options));
    check_groups_partition(walk, tree, grouping);
  };
  search_equals_brute_force();
  std::mt19937_64 random(62);
  std::uniform_real_distribution<double> jitter(-0.02, 0.02);
  for (auto& x : set.x)
    for (auto& component : x) component += jitter(random);
  tree.refit(set.x.data(), set.m.data(), set.h.data());
  search_equals_brute_force();
  set = gaussian_blobs<3>(2000, 2, 0.05, 63);
  sort_by_key(set, nt::curve::hilbert);
  tree.build(set.keys.data(), set.x.data(), set.m.data(), set.h.data(), set.size(), {8, false});
  search_equals_brute_force();
}

TEST_CASE("sums in canonical order are reproducible across thread schedules", "[ntree][group_walk]") {
  auto set = uniform<3>(3000, 77, 60);
  sort_by_key(set, nt::curve::hilbert);
  const auto tree = build_tree(set, 16);
  const auto space = nt::domain<3>::open();
  const auto density = [&](nt::group_walk<3>& walk) {
    std::vector<double> rho(set.size(), 0);
    walk.for_each_neighbour(tree, space, [&](std::size_t a, std::size_t b) {
      rho[a] += set.m[b] * std::exp(-nt::distance_squared<3>(set.x[a], set.x[b]));
    });
    return rho;
  };
  nt::group_walk<3> small({}, {4, 0});
  nt::group_walk<3> large({}, {128, 0});
  const auto first = density(small);
  const auto second = density(large);
  for (std::size_t a = 0; a < set.size(); ++a) REQUIRE(first[a] == second[a]);  // bitwise
}
