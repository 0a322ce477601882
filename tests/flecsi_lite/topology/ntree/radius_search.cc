// Tests of the per-target radius search: gather and symmetric neighbour lists, by callback and
// in CSR form, for all or some targets, equal exactly (same order) to the brute-force search.
#include "flecsi_lite/topology/ntree/search/radius_search.hh"
#include "tests/flecsi_lite/topology/ntree/search_checks.hh"

#include <catch2/catch.hpp>

namespace nt = flecsi_lite::topology::ntree;
using namespace ntree_test;

namespace {

template<int D>
void check_radius_search(nt::curve order) {
  const auto space = nt::domain<D>::open();
  for (const auto& set : search_sets<D>(order)) {
    const auto tree = build_tree(set, 8);
    const auto mask = random_targets(set.size(), 17);
    for (const nt::interaction kind : {nt::interaction::gather, nt::interaction::symmetric}) {
      for (const std::uint8_t* targets : {static_cast<const std::uint8_t*>(nullptr), mask.data()}) {
        const nt::search_options options{kind, 2.0, targets};
        const auto expected = brute_force(set, space, options);
        REQUIRE(expected.total() > set.size());  // the sets do have neighbours
        nt::radius_search<D> search(options);
        nt::neighbour_lists found;
        search.find_neighbours(tree, space, found);
        require_equal(found, expected);
        require_equal(lists_from_callback(search, tree, space), expected);
        // The two-argument functor gets the same pairs.
        std::vector<std::size_t> counts(set.size(), 0);
        search.for_each_neighbour(tree, space, [&](std::size_t a, std::size_t) { ++counts[a]; });
        for (std::size_t a = 0; a < set.size(); ++a) REQUIRE(counts[a] == expected.count(a));
      }
    }
  }
}

}  // namespace

TEST_CASE("radius search equals brute force in 1D", "[ntree][search]") { check_radius_search<1>(nt::curve::hilbert); }

TEST_CASE("radius search equals brute force in 2D", "[ntree][search]") {
  check_radius_search<2>(nt::curve::hilbert);
  check_radius_search<2>(nt::curve::morton);
}

TEST_CASE("radius search equals brute force in 3D", "[ntree][search]") { check_radius_search<3>(nt::curve::hilbert); }

TEST_CASE("ball query around arbitrary points", "[ntree][search]") {
  auto set = uniform<3>(2000, 44);
  sort_by_key(set, nt::curve::hilbert);
  const auto tree = build_tree(set);
  std::mt19937_64 random(2);
  std::uniform_real_distribution<double> unit(-0.2, 1.2);
  for (int trial = 0; trial < 50; ++trial) {
    const nt::point<3> centre{unit(random), unit(random), unit(random)};
    const double radius = 0.05 + 0.2 * unit(random);
    std::vector<std::size_t> found, expected;
    nt::for_each_within<3>(tree, nt::domain<3>::open(), centre, radius,
                           [&](std::size_t b, nt::shift_code) { found.push_back(b); });
    for (std::size_t b = 0; b < set.size(); ++b)
      if (nt::distance_squared<3>(centre, set.x[b]) < radius * radius) expected.push_back(b);
    REQUIRE(found == expected);
  }
}

TEST_CASE("searches on an empty tree find nothing", "[ntree][search]") {
  nt::hashed_tree<2> tree;
  tree.build(nullptr, nullptr, nullptr, nullptr, 0);
  nt::radius_search<2> search;
  nt::neighbour_lists lists;
  search.find_neighbours(tree, nt::domain<2>::open(), lists);
  REQUIRE(lists.size() == 0);
  REQUIRE(lists.total() == 0);
}
