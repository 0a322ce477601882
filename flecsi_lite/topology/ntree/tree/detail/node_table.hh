// The hash table of the hashed oct-tree (Warren & Salmon 1993; Warren 2013, "2HOT"): maps a node
// key to the node's index, by open addressing with linear probing and Fibonacci hashing.
#pragma once

#include "flecsi_lite/topology/ntree/sfc/keys.hh"

#include <cassert>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace flecsi_lite::topology::ntree {

/// Open addressing rather than std::unordered_map: one flat array of 4-byte node indices (the
/// keys stay in the nodes), no allocation per node, a load factor at most 1/2 so that probes
/// stay short, and cache-friendly probing. The table is built once per tree and only read.
class node_table {
 public:
  static constexpr std::uint32_t npos = ~std::uint32_t{0};

  /// Maps key_of(i) to i for every i < n. Precondition: the keys are distinct.
  template<class KeyOf>
  void build(std::size_t n, const KeyOf& key_of) {
    assert(n < npos);
    std::size_t capacity = 16;
    while (capacity < 2 * n) capacity *= 2;
    shift_ = 64;
    for (std::size_t c = capacity; c > 1; c >>= 1) --shift_;
    slots_.assign(capacity, npos);
    const std::size_t mask = capacity - 1;
    for (std::size_t i = 0; i < n; ++i) {
      const key_type key = key_of(i);
      std::size_t at = home(key);
      while (slots_[at] != npos) {
        assert(key_of(slots_[at]) != key);
        at = (at + 1) & mask;
      }
      slots_[at] = static_cast<std::uint32_t>(i);
    }
  }

  /// Index mapped to `key`, or npos when no entry has that key; key_of as given to build.
  template<class KeyOf>
  std::uint32_t find(key_type key, const KeyOf& key_of) const {
    if (slots_.empty()) return npos;
    const std::size_t mask = slots_.size() - 1;
    for (std::size_t at = home(key);; at = (at + 1) & mask) {
      const std::uint32_t index = slots_[at];
      if (index == npos || key_of(index) == key) return index;
    }
  }

  std::size_t capacity() const { return slots_.size(); }
  std::size_t bytes() const { return slots_.size() * sizeof(std::uint32_t); }

 private:
  // Fibonacci hashing: the top bits of key * 2^64/phi spread nearby keys over the table.
  std::size_t home(key_type key) const { return static_cast<std::size_t>((key * 0x9e3779b97f4a7c15ull) >> shift_); }

  std::vector<std::uint32_t> slots_;
  int shift_ = 64;
};

}  // namespace flecsi_lite::topology::ntree
