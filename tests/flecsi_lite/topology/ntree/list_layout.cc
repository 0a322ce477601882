// Tests of the list layouts of the group walk (list_layout): shift codes packed into the entries
// carry the same neighbours and shifts as separate ones, on periodic and open domains; rows
// coded as runs decode to the packed entries, bit for bit, and any row survives its coding; renamed
// rows and entries (the local tree's storage order) are the default lists, renamed; a
// repeated search writes the lists in place, with little spare room, walking twice only when
// the lists outgrow the room of the last ones; and one walk's searches may alternate rows as
// runs and packed rows.
#include "flecsi_lite/topology/ntree/search/group_walk.hh"
#include "tests/flecsi_lite/topology/ntree/search_checks.hh"

#include <catch2/catch.hpp>

#include <algorithm>
#include <random>

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

// Decodes lists kept as runs into packed lists.
nt::neighbour_lists decoded(const nt::neighbour_lists& coded) {
  REQUIRE(coded.in_runs);
  REQUIRE(coded.neighbours.empty());
  nt::neighbour_lists lists;
  lists.offsets.assign(1, 0);
  for (std::size_t a = 0; a < coded.size(); ++a) {
    std::vector<std::uint32_t> row(coded.count(a) + nt::runs::decode_padding);
    if (coded.count(a) > 0)
      REQUIRE(nt::runs::decode_row(coded.runs.data() + coded.offsets[a], row.data()) == coded.count(a));
    row.resize(coded.count(a));
    lists.neighbours.insert(lists.neighbours.end(), row.begin(), row.end());
    lists.offsets.push_back(lists.neighbours.size());
  }
  return lists;
}

// The packed lists of a fresh walk with `options` (the reference of the searches under test).
nt::neighbour_lists packed_lists(const nt::hashed_tree<3>& tree, const nt::domain<3>& space,
                                 const nt::search_options& options) {
  nt::list_layout layout;
  layout.shifts = nt::shift_storage::packed;
  nt::neighbour_lists lists;
  nt::group_walk<3>(options).find_neighbours(tree, space, lists, layout);
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

TEST_CASE("rows coded as runs decode to the packed entries", "[ntree][list_layout]") {
  auto set = uniform<3>(3000, 95, 60);
  sort_by_key(set, nt::curve::morton);
  const auto tree = build_tree(set, 16);
  const auto mask = random_targets(set.size(), 96);
  for (const bool periodic : {true, false})
    for (const bool some_targets : {false, true}) {
      const auto space = unit_box(periodic);
      nt::group_walk<3> walk({nt::interaction::symmetric, 2.0, some_targets ? mask.data() : nullptr});
      nt::neighbour_lists packed, coded;
      nt::list_layout layout;
      layout.shifts = nt::shift_storage::packed;
      walk.find_neighbours(tree, space, packed, layout);
      layout.shifts = nt::shift_storage::runs;
      walk.find_neighbours(tree, space, coded, layout);
      REQUIRE(coded.size() == packed.size());
      REQUIRE(coded.total() == packed.total());
      const auto lists = decoded(coded);
      REQUIRE(lists.offsets == packed.offsets);
      REQUIRE(lists.neighbours == packed.neighbours);
      // Runs of consecutive neighbours (the particles of a leaf): well under 2 bytes an entry.
      REQUIRE(coded.runs.size() < 2 * coded.total());
    }
}

TEST_CASE("any row survives its coding as runs", "[ntree][list_layout]") {
  std::mt19937 random(97);
  const auto check = [](const std::vector<std::uint32_t>& row) {
    std::vector<std::uint8_t> bytes(nt::runs::max_row_bytes(row.size()));
    const std::size_t size = nt::runs::encode_row(row.data(), row.size(), bytes.data());
    REQUIRE(size == nt::runs::row_bytes(row.data(), row.size()));
    REQUIRE(size <= bytes.size());
    REQUIRE(nt::runs::row_count(bytes.data()) == row.size());
    std::vector<std::uint32_t> back(row.size() + nt::runs::decode_padding, 7);
    REQUIRE(nt::runs::decode_row(bytes.data(), back.data()) == row.size());
    back.resize(row.size());
    REQUIRE(back == row);
  };
  check({});
  const std::uint32_t last = nt::packed_index_mask;
  // The largest index under every shift code, jumps backwards, repeats, a run across the index
  // bits' end (b = 2^27 - 1 then b = 0 under the next code is the next 32-bit value).
  check({nt::packed_entry(last, 26), nt::packed_entry(0, 0), nt::packed_entry(last, 0), nt::packed_entry(0, 1)});
  check({nt::packed_entry(5, 13), nt::packed_entry(5, 13), nt::packed_entry(4, 13), nt::packed_entry(5, 12)});
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<std::uint32_t> row(random() % 300);
    std::uint32_t b = random() % (last + 1);
    for (auto& entry : row) {
      const unsigned pick = random() % 8;
      b = pick < 5 ? (b + 1) & last : pick < 7 ? random() % (last + 1) : b;  // mostly runs
      entry = nt::packed_entry(b, static_cast<nt::shift_code>(random() % 4 == 0 ? random() % 27 : 13));
    }
    if (trial % 2)
      std::sort(row.begin(), row.end(),
                [](std::uint32_t x, std::uint32_t y) { return nt::packed_neighbour(x) < nt::packed_neighbour(y); });
    check(row);
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

  // The same with rows coded as runs: regions in bytes, a second pass when they are outgrown.
  nt::list_layout layout;
  layout.shifts = nt::shift_storage::runs;
  nt::group_walk<3> coding(options);
  nt::neighbour_lists coded;
  coding.find_neighbours(tree, space, coded, layout);
  coding.find_neighbours(tree, space, coded, layout);
  REQUIRE(coding.repeated_list_passes() == 1);
  REQUIRE(decoded(coded).neighbours == packed_lists(tree, space, options).neighbours);
  coding.find_neighbours(grown_tree, space, coded, layout);
  REQUIRE(coding.repeated_list_passes() == 2);
  REQUIRE(decoded(coded).neighbours == packed_lists(grown_tree, space, options).neighbours);
  REQUIRE(coded.runs.capacity() <= coded.runs.size() + coded.runs.size() / 8);
}

TEST_CASE("one walk's searches may change the kind of their rows", "[ntree][list_layout]") {
  // As the SPH steps with individual time steps do: every particle's rows as runs, then a few
  // targets' rows packed, and so on, on one walk (whose mask the caller rewrites).
  auto set = uniform<3>(2000, 94, 80);
  sort_by_key(set, nt::curve::hilbert);
  const auto tree = build_tree(set, 16);
  const auto space = unit_box(true);
  const auto few = random_targets(set.size(), 16);
  const std::vector<std::uint8_t> all(set.size(), 1);
  const auto expected_all = packed_lists(tree, space, {nt::interaction::symmetric, 2.0, all.data()});
  const auto expected_few = packed_lists(tree, space, {nt::interaction::symmetric, 2.0, few.data()});
  std::vector<std::uint8_t> mask(set.size());
  nt::group_walk<3> walk({nt::interaction::symmetric, 2.0, mask.data()});
  nt::neighbour_lists lists;
  std::size_t passes_after_first_round = 0;
  for (int round = 0; round < 3; ++round) {
    for (const bool every : {true, false}) {
      nt::list_layout layout;
      layout.shifts = every ? nt::shift_storage::runs : nt::shift_storage::packed;
      std::copy((every ? all : few).begin(), (every ? all : few).end(), mask.begin());
      walk.find_neighbours(tree, space, lists, layout);
      if (every) {
        REQUIRE(lists.neighbours.capacity() == 0);  // the packed rows' array is freed
        const auto rows = decoded(lists);
        REQUIRE(rows.offsets == expected_all.offsets);
        REQUIRE(rows.neighbours == expected_all.neighbours);
      } else {
        REQUIRE(lists.runs.capacity() == 0);
        REQUIRE(lists.offsets == expected_few.offsets);
        REQUIRE(lists.neighbours == expected_few.neighbours);
      }
    }
    if (round == 0) passes_after_first_round = walk.repeated_list_passes();
  }
  // Each kind keeps the room of its own regions (bytes of runs, entries): after the first search
  // of each, no search walks twice.
  REQUIRE(passes_after_first_round == 2);
  REQUIRE(walk.repeated_list_passes() == passes_after_first_round);
}
