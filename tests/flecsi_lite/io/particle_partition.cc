// Block partition for parallel reads: every element read exactly once, in rank order, with
// block sizes differing by at most one, for many lengths and rank counts.
#include <catch2/catch.hpp>

#include "flecsi_lite/io/particle_partition.hh"

using flecsi_lite::io::block_slice;
using flecsi_lite::io::slice;

TEST_CASE("block slices tile the array in rank order and are balanced") {
  for (std::uint64_t n : {0ull, 1ull, 2ull, 3ull, 7ull, 64ull, 1000ull, 1000003ull})
    for (int p : {1, 2, 3, 4, 7, 16, 1000}) {
      std::uint64_t next = 0, smallest = n, largest = 0;
      for (int r = 0; r < p; ++r) {
        const slice s = block_slice(n, r, p);
        CHECK(s.offset == next);  // contiguous, no gap, no overlap
        next += s.count;
        smallest = std::min(smallest, s.count);
        largest = std::max(largest, s.count);
      }
      CHECK(next == n);
      CHECK(largest - smallest <= 1);
    }
}

TEST_CASE("the first n mod p ranks hold the extra elements") {
  CHECK(block_slice(10, 0, 4) == slice{0, 3});
  CHECK(block_slice(10, 1, 4) == slice{3, 3});
  CHECK(block_slice(10, 2, 4) == slice{6, 2});
  CHECK(block_slice(10, 3, 4) == slice{8, 2});
  CHECK(block_slice(2, 3, 4) == slice{2, 0});
  static_assert(block_slice(5, 1, 2).offset == 3, "usable in constant expressions");
}
