// Tests of the list layouts of the group walk (list_layout): shift codes packed into the entries
// carry the same neighbours and shifts as separate ones, on periodic and open domains; renamed
// rows and entries (the local tree's storage order) are the default lists, renamed; and a
// repeated search writes the lists in place, with little spare room, walking twice only when
// the lists outgrow the room of the last ones.
#include "flecsi_lite/topology/ntree/search/group_walk.hh"
#include "tests/flecsi_lite/topology/ntree/search_checks.hh"

#include <catch2/catch.hpp>

namespace nt = flecsi_lite::topology::ntree;
using namespace ntree_test;

namespace {

// Decodes packed lists into the separate form (shift codes only on a periodic domain).
nt::neighbour_lists unpacked(const nt::neighbour_lists& packed, bool periodic) {
  nt::neighbour_lists lists;
  lists.offsets = packed.offsets;
  for (const std::uint32_t entry : packed.neighbours) {
    lists.neighbours.push_back(nt::packed_neighbour(entry));
    if (periodic) lists.shifts.push_back(nt::packed_shift(entry));
  }
  return lists;
}

nt::domain<3> unit_box(bool periodic) {
  nt::domain<3> space = nt::domain<3>::open();
  space.periodic.fill(periodic);
  return space;
}

}  // namespace

TEST_CASE("packed shift codes equal separate ones", "[ntree][list_layout]") {
  auto set = uniform<3>(2000, 91, 60);
  sort_by_key(set, nt::curve::hilbert);
  const auto tree = build_tree(set, 16);
  for (const bool periodic : {true, false}) {
    const auto space = unit_box(periodic);
    for (const nt::interaction kind : {nt::interaction::gather, nt::interaction::symmetric}) {
      nt::group_walk<3> walk({kind, 2.0, nullptr});
      nt::neighbour_lists separate, packed;
      walk.find_neighbours(tree, space, separate);
      nt::list_layout layout;
      layout.shifts = nt::shift_storage::packed;
      walk.find_neighbours(tree, space, packed, layout);
      REQUIRE(packed.shifts.empty());
      require_equal(unpacked(packed, periodic), separate);
      require_equal(separate, brute_force(set, space, {kind, 2.0, nullptr}));
      if (!periodic)
        for (const std::uint32_t entry : packed.neighbours) REQUIRE(nt::packed_shift(entry) == nt::zero_shift<3>);
    }
  }
}

TEST_CASE("renamed rows and entries are the lists renamed", "[ntree][list_layout]") {
  auto set = uniform<3>(3000, 92, 50);
  sort_by_key(set, nt::curve::hilbert);
  const auto tree = build_tree(set, 8);
  const auto space = unit_box(true);
  const auto mask = random_targets(set.size(), 93);
  // Targets take rows 0, 1, ... in their order; every particle is renamed (targets to their
  // row, the others after them), as the local tree renames sorted to storage indices.
  std::vector<std::size_t> rename(set.size());
  std::size_t targets = 0;
  for (std::size_t a = 0; a < set.size(); ++a)
    if (mask[a]) rename[a] = targets++;
  for (std::size_t a = 0, other = targets; a < set.size(); ++a)
    if (!mask[a]) rename[a] = other++;

  const nt::search_options options{nt::interaction::symmetric, 2.0, mask.data()};
  nt::group_walk<3> walk(options, {16, 0});
  nt::neighbour_lists plain, renamed;
  walk.find_neighbours(tree, space, plain);
  nt::list_layout layout;
  layout.rename = rename.data();
  layout.rows = targets;
  walk.find_neighbours(tree, space, renamed, layout);

  REQUIRE(renamed.size() == targets);
  REQUIRE(renamed.total() == plain.total());
  for (std::size_t a = 0; a < set.size(); ++a) {
    if (!mask[a]) continue;
    const std::size_t row = rename[a];
    REQUIRE(renamed.count(row) == plain.count(a));
    for (std::size_t i = 0; i < plain.count(a); ++i) {
      REQUIRE(renamed.neighbours[renamed.offsets[row] + i] == rename[plain.neighbours[plain.offsets[a] + i]]);
      REQUIRE(renamed.shifts[renamed.offsets[row] + i] == plain.shifts[plain.offsets[a] + i]);
    }
  }
}

TEST_CASE("repeated searches write the lists in place", "[ntree][list_layout]") {
  auto set = uniform<3>(2000, 94, 80);
  sort_by_key(set, nt::curve::hilbert);
  const auto tree = build_tree(set, 16);
  const auto space = unit_box(true);
  const nt::search_options options{nt::interaction::symmetric, 2.0, nullptr};
  const auto expected = brute_force(set, space, options);
  nt::group_walk<3> walk(options);
  nt::neighbour_lists lists;
  walk.find_neighbours(tree, space, lists);  // regions unknown: a counting pass, then the lists
  require_equal(lists, expected);
  REQUIRE(walk.repeated_list_passes() == 1);
  walk.find_neighbours(tree, space, lists);  // regions from the first search
  require_equal(lists, expected);
  const std::uint32_t* storage = lists.neighbours.data();
  walk.find_neighbours(tree, space, lists);  // the steady state: the same arrays, one pass each
  require_equal(lists, expected);
  REQUIRE(lists.neighbours.data() == storage);
  REQUIRE(walk.repeated_list_passes() == 1);
  REQUIRE(lists.neighbours.capacity() <= lists.total() + lists.total() / 8);

  // Lists that outgrow their regions (larger h) take a second pass, and are right again.
  auto grown = set;
  for (double& h : grown.h) h *= 1.2;
  const auto grown_tree = build_tree(grown, 16);
  walk.find_neighbours(grown_tree, space, lists);
  REQUIRE(walk.repeated_list_passes() == 2);
  require_equal(lists, brute_force(grown, space, options));
  REQUIRE(lists.neighbours.capacity() <= lists.total() + lists.total() / 8);
}
