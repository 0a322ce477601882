// Tests of the (key, id) ordering: the radix-sort permutation equals a comparison sort, ties
// between equal keys go by id, and the sorted order does not depend on the input order.
#include "flecsi_lite/topology/ntree/sfc/ordering.hh"
#include "tests/flecsi_lite/topology/ntree/particle_sets.hh"

#include <catch2/catch.hpp>

#include <algorithm>
#include <numeric>
#include <random>
#include <vector>

namespace nt = flecsi_lite::topology::ntree;

namespace {

std::vector<std::size_t> reference_permutation(const std::vector<nt::key_type>& keys,
                                               const std::vector<std::uint64_t>& ids) {
  std::vector<std::size_t> order(keys.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(),
            [&](std::size_t a, std::size_t b) { return keys[a] < keys[b] || (keys[a] == keys[b] && ids[a] < ids[b]); });
  return order;
}

// Sorted (key, id) pairs obtained through the permutation of the library.
std::vector<std::pair<nt::key_type, std::uint64_t>> sorted_pairs(const std::vector<nt::key_type>& keys,
                                                                 const std::vector<std::uint64_t>& ids) {
  const auto permutation = nt::sort_permutation(keys.data(), ids.data(), keys.size());
  std::vector<std::pair<nt::key_type, std::uint64_t>> pairs;
  for (const std::size_t i : permutation) pairs.emplace_back(keys[i], ids[i]);
  return pairs;
}

void check_against_reference(const std::vector<nt::key_type>& keys, const std::vector<std::uint64_t>& ids) {
  const auto permutation = nt::sort_permutation(keys.data(), ids.data(), keys.size());
  REQUIRE(permutation == reference_permutation(keys, ids));
  std::vector<nt::key_type> sorted_keys(keys.size());
  std::vector<std::uint64_t> sorted_ids(keys.size());
  nt::apply_permutation(permutation, keys.data(), sorted_keys.data());
  nt::apply_permutation(permutation, ids.data(), sorted_ids.data());
  REQUIRE(nt::is_sorted(sorted_keys.data(), sorted_ids.data(), keys.size()));
}

}  // namespace

TEST_CASE("sort permutation equals a comparison sort on (key, id)", "[ntree][ordering]") {
  std::mt19937_64 random(21);
  for (const std::size_t n : {0, 1, 2, 100, 255, 256, 3000, 20000}) {
    std::vector<nt::key_type> keys(n);
    std::vector<std::uint64_t> ids(n);
    std::iota(ids.begin(), ids.end(), std::uint64_t{0});
    std::shuffle(ids.begin(), ids.end(), random);
    // Full 64-bit keys exercise every radix pass.
    for (auto& key : keys) key = random() | std::uint64_t{1} << 63;
    check_against_reference(keys, ids);
    // Few distinct keys: most comparisons are ties broken by id.
    for (auto& key : keys) key = (std::uint64_t{1} << 63) + random() % 7;
    check_against_reference(keys, ids);
  }
}

TEST_CASE("sorted order is total and independent of the input order", "[ntree][ordering]") {
  for (const nt::curve order : {nt::curve::morton, nt::curve::hilbert}) {
    // Coincident particles share keys: only the ids order them.
    auto set = ntree_test::coincident<3>(4000, 100, 5);
    std::vector<nt::key_type> keys(set.size());
    nt::compute_keys<3>(order, set.domain, set.x.data(), set.size(), keys.data());
    const auto expected = sorted_pairs(keys, set.id);
    for (std::size_t i = 1; i < expected.size(); ++i) REQUIRE(expected[i - 1] < expected[i]);

    std::mt19937_64 random(8);
    for (int trial = 0; trial < 3; ++trial) {
      std::vector<std::size_t> shuffle(set.size());
      std::iota(shuffle.begin(), shuffle.end(), std::size_t{0});
      std::shuffle(shuffle.begin(), shuffle.end(), random);
      std::vector<nt::key_type> shuffled_keys(set.size());
      std::vector<std::uint64_t> shuffled_ids(set.size());
      nt::apply_permutation(shuffle, keys.data(), shuffled_keys.data());
      nt::apply_permutation(shuffle, set.id.data(), shuffled_ids.data());
      REQUIRE(sorted_pairs(shuffled_keys, shuffled_ids) == expected);
    }
  }
}

TEST_CASE("equal (key, id) pairs keep their input order", "[ntree][ordering]") {
  const std::vector<nt::key_type> keys(300, 42);
  const std::vector<std::uint64_t> ids(300, 7);
  const auto permutation = nt::sort_permutation(keys.data(), ids.data(), keys.size());
  for (std::size_t i = 0; i < permutation.size(); ++i) REQUIRE(permutation[i] == i);
  REQUIRE_FALSE(nt::is_sorted(keys.data(), ids.data(), keys.size()));
}
