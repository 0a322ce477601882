// Tests of periodic searches: along any subset of axes, in boxes of unequal periods, the radius
// search and the group walk find exactly the brute-force image pairs with their shifts, which
// agree with an independent minimum-image computation; unsafe uses are refused.
#include "flecsi_lite/topology/ntree/search/group_walk.hh"
#include "flecsi_lite/topology/ntree/search/radius_search.hh"
#include "tests/flecsi_lite/topology/ntree/search_checks.hh"

#include <catch2/catch.hpp>

#include <cmath>
#include <stdexcept>

namespace nt = flecsi_lite::topology::ntree;
using namespace ntree_test;

namespace {

// Moves a particle set from the unit box into `bounds`.
template<int D>
particle_set<D> stretched(particle_set<D> set, const nt::box<D>& bounds) {
  double volume_scale = 1;
  for (int k = 0; k < D; ++k) volume_scale *= bounds.hi[k] - bounds.lo[k];
  for (auto& x : set.x)
    for (int k = 0; k < D; ++k) x[k] = bounds.lo[k] + x[k] * (bounds.hi[k] - bounds.lo[k]);
  for (auto& h : set.h) h *= std::pow(volume_scale, 1.0 / D);
  set.domain = bounds;
  return set;
}

// Independent reference: minimum image of each separation, and the shift it implies.
template<int D>
void check_minimum_image(const particle_set<D>& set, const nt::domain<D>& space, const nt::neighbour_lists& lists,
                         double support) {
  const auto shifts = space.shift_table();
  std::size_t pairs = 0;
  for (std::size_t a = 0; a < set.size(); ++a) {
    for (std::size_t b = 0; b < set.size(); ++b) {
      double r2 = 0;
      nt::point<D> image_shift{};
      for (int k = 0; k < D; ++k) {
        double d = set.x[a][k] - set.x[b][k];
        if (space.periodic[k]) {
          image_shift[k] = std::round(d / space.period(k)) * space.period(k);
          d -= image_shift[k];
        }
        r2 += d * d;
      }
      const double radius = support * set.h[a];
      if (!(r2 < radius * radius)) continue;
      ++pairs;
      const auto begin = lists.neighbours.begin() + lists.offsets[a];
      const auto end = lists.neighbours.begin() + lists.offsets[a + 1];
      const auto found = std::lower_bound(begin, end, static_cast<std::uint32_t>(b));
      REQUIRE(found != end);
      REQUIRE(*found == b);
      const auto shift = shifts[lists.shifts[found - lists.neighbours.begin()]];
      for (int k = 0; k < D; ++k) REQUIRE(shift[k] == Approx(image_shift[k]));
    }
  }
  REQUIRE(pairs == lists.total());
}

template<int D>
void check_periodic(const nt::box<D>& bounds, const std::array<bool, D>& periodic) {
  nt::domain<D> space{bounds, periodic};
  const std::size_t per_axis = D == 1 ? 800 : D == 2 ? 30 : 9;
  const std::size_t n = D == 3 ? 800 : 1200;  // brute force tries 27 images per pair in 3D
  std::vector<particle_set<D>> sets;
  sets.push_back(stretched(uniform<D>(n, 500 + D, 30), bounds));
  sets.push_back(stretched(lattice<D>(per_axis, 1.0), bounds));
  sets.push_back(stretched(coincident<D>(n, 30, 600 + D, 30), bounds));
  for (std::size_t s = 0; s < sets.size(); ++s) {
    auto& set = sets[s];
    sort_by_key(set, nt::curve::hilbert);
    const auto tree = build_tree(set, 8);
    const auto mask = random_targets(set.size(), 29);
    for (const nt::interaction kind : {nt::interaction::gather, nt::interaction::symmetric}) {
      for (const std::uint8_t* targets : {static_cast<const std::uint8_t*>(nullptr), mask.data()}) {
        const nt::search_options options{kind, 2.0, targets};
        const auto expected = brute_force(set, space, options);
        REQUIRE(expected.shifts.size() == expected.total());
        if (s == 0 && kind == nt::interaction::gather && targets == nullptr)
          check_minimum_image(set, space, expected, options.support);

        nt::radius_search<D> search(options);
        nt::neighbour_lists found;
        search.find_neighbours(tree, space, found);
        require_equal(found, expected);
        require_equal(lists_from_callback(search, tree, space), expected);

        for (const nt::group_options grouping : {nt::group_options{4, 0}, {48, 0}}) {
          nt::group_walk<D> walk(options, grouping);
          walk.find_neighbours(tree, space, found);
          require_equal(found, expected);
          require_equal(lists_from_callback(walk, tree, space), expected);
        }
      }
    }
  }
}

}  // namespace

TEST_CASE("periodic searches in 1D", "[ntree][periodic]") { check_periodic<1>({{-1.0}, {2.0}}, {true}); }

TEST_CASE("periodic searches in 2D along one or both axes", "[ntree][periodic]") {
  const nt::box<2> bounds{{0.0, -0.25}, {2.0, 0.75}};
  check_periodic<2>(bounds, {true, false});
  check_periodic<2>(bounds, {false, true});
  check_periodic<2>(bounds, {true, true});
}

TEST_CASE("periodic searches in 3D", "[ntree][periodic]") {
  const nt::box<3> bounds{{0.0, 0.0, 0.0}, {1.0, 1.5, 1.0}};
  check_periodic<3>(bounds, {true, true, true});
  check_periodic<3>(bounds, {false, false, true});
}

TEST_CASE("corner particles see diagonal images", "[ntree][periodic]") {
  // Two particles at opposite corners are neighbours only through the image shifted on all axes.
  particle_set<3> set;
  set.x = {{0.01, 0.01, 0.01}, {0.99, 0.99, 0.99}};
  set.m = {1, 1};
  set.h = {0.02, 0.02};
  set.id = {1, 2};
  set.domain = {{0, 0, 0}, {1, 1, 1}};
  sort_by_key(set, nt::curve::hilbert);
  const auto tree = build_tree(set);
  const nt::domain<3> space{set.domain, {true, true, true}};
  nt::neighbour_lists found;
  nt::group_walk<3> walk;
  walk.find_neighbours(tree, space, found);
  // Each particle sees itself (no shift) and the other through the diagonal image.
  REQUIRE(found.total() == 4);
  for (std::size_t a = 0; a < 2; ++a) {
    REQUIRE(found.count(a) == 2);
    for (std::size_t j = found.offsets[a]; j < found.offsets[a + 1]; ++j) {
      const auto shift = space.shift(found.shifts[j]);
      const double sign = found.neighbours[j] == a ? 0.0 : set.x[a][0] < 0.5 ? -1.0 : 1.0;
      for (int k = 0; k < 3; ++k) REQUIRE(shift[k] == sign);  // x_b + shift is next to x_a
    }
  }
}

TEST_CASE("periodic searches refuse what they cannot do exactly", "[ntree][periodic]") {
  auto set = uniform<2>(500, 3, 30);
  sort_by_key(set, nt::curve::hilbert);
  const auto tree = build_tree(set);
  const nt::domain<2> space{set.domain, {true, false}};
  nt::group_walk<2> walk;
  // A functor without the shift could not place the images.
  REQUIRE_THROWS_AS(walk.for_each_neighbour(tree, space, [](std::size_t, std::size_t) {}), std::invalid_argument);
  // A radius beyond half a period would see one source under two shifts.
  nt::group_walk<2> wide({nt::interaction::gather, 1e3, nullptr});
  nt::neighbour_lists lists;
  REQUIRE_THROWS_AS(wide.find_neighbours(tree, space, lists), std::invalid_argument);
  nt::radius_search<2> wide_search({nt::interaction::gather, 1e3, nullptr});
  REQUIRE_THROWS_AS(wide_search.find_neighbours(tree, space, lists), std::invalid_argument);
  // The same search on an open domain is fine.
  REQUIRE_NOTHROW(wide.find_neighbours(tree, nt::domain<2>::open(), lists));
}
