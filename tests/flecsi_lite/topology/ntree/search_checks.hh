// Shared checks of the ntree search tests: tree construction from a particle set, exact
// comparison of neighbour lists with the brute-force reference, and callback results as lists.
#pragma once

#include "flecsi_lite/topology/ntree/reference/brute_force.hh"
#include "flecsi_lite/topology/ntree/search/neighbour_lists.hh"
#include "flecsi_lite/topology/ntree/tree/hashed_tree.hh"
#include "tests/flecsi_lite/topology/ntree/particle_sets.hh"

#include <catch2/catch.hpp>

#include <random>
#include <vector>

namespace ntree_test {

template<int D>
nt::hashed_tree<D> build_tree(const particle_set<D>& set, std::size_t bucket = 16) {
  nt::hashed_tree<D> tree;
  tree.build(set.keys.data(), set.x.data(), set.m.data(), set.h.data(), set.size(), {bucket, false});
  return tree;
}

inline void require_ascending(const nt::neighbour_lists& lists) {
  for (std::size_t a = 0; a < lists.size(); ++a)
    for (std::size_t j = lists.offsets[a] + 1; j < lists.offsets[a + 1]; ++j)
      REQUIRE(lists.neighbours[j - 1] < lists.neighbours[j]);
}

/// Exact equality: same neighbours, same order, same image shifts.
inline void require_equal(const nt::neighbour_lists& found, const nt::neighbour_lists& expected) {
  REQUIRE(found.offsets.size() == expected.offsets.size());
  REQUIRE(found.offsets == expected.offsets);
  REQUIRE(found.neighbours == expected.neighbours);
  REQUIRE(found.shifts == expected.shifts);
  require_ascending(found);
}

template<int D>
nt::neighbour_lists brute_force(const particle_set<D>& set, const nt::domain<D>& space,
                                const nt::search_options& options) {
  nt::neighbour_lists lists;
  nt::brute_force_neighbours<D>(set.x.data(), set.h.data(), set.size(), space, options, lists);
  return lists;
}

/// The shift code of a shift vector that a callback received.
template<int D>
nt::shift_code code_of(const nt::point<D>& shift) {
  int code = 0;
  for (int k = D - 1; k >= 0; --k) code = 3 * code + (shift[k] == 0 ? 1 : shift[k] < 0 ? 0 : 2);
  return static_cast<nt::shift_code>(code);
}

/// Runs search.for_each_neighbour with a functor taking the shift and turns the calls into
/// lists; also checks that the calls for each target come in ascending order.
template<int D, class Search>
nt::neighbour_lists lists_from_callback(Search& search, const nt::hashed_tree<D>& tree, const nt::domain<D>& space) {
  const std::size_t n = tree.size();
  std::vector<std::vector<std::pair<std::uint32_t, nt::shift_code>>> calls(n);
  search.for_each_neighbour(tree, space, [&](std::size_t a, std::size_t b, const nt::point<D>& shift) {
    calls[a].emplace_back(static_cast<std::uint32_t>(b), code_of<D>(shift));
  });
  nt::neighbour_lists lists;
  lists.offsets.assign(n + 1, 0);
  for (std::size_t a = 0; a < n; ++a) {
    lists.offsets[a + 1] = lists.offsets[a] + calls[a].size();
    for (const auto& [b, code] : calls[a]) {
      lists.neighbours.push_back(b);
      if (space.any_periodic()) lists.shifts.push_back(code);
    }
  }
  return lists;
}

/// About half the particles, chosen at random, as targets.
inline std::vector<std::uint8_t> random_targets(std::size_t n, std::uint64_t seed) {
  std::mt19937_64 random(seed);
  std::vector<std::uint8_t> mask(n);
  for (auto& flag : mask) flag = static_cast<std::uint8_t>(random() & 1);
  return mask;
}

/// The particle sets every search is checked on, in dimension D, sorted in `order`.
template<int D>
std::vector<particle_set<D>> search_sets(nt::curve order) {
  std::vector<particle_set<D>> sets;
  const std::size_t per_axis = D == 1 ? 1500 : D == 2 ? 40 : 12;
  sets.push_back(uniform<D>(1500, 100 + D));
  sets.push_back(lattice<D>(per_axis, 1.0));  // 2h = 2 spacings: distances hit 2h exactly
  sets.push_back(gaussian_blobs<D>(1500, 3, 0.02, 200 + D));
  sets.push_back(coincident<D>(1500, 40, 300 + D));
  for (auto& set : sets) sort_by_key(set, order);
  return sets;
}

}  // namespace ntree_test
