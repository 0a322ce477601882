// The hash table of the hashed oct-tree (Warren & Salmon 1993; Warren 2013, "2HOT"): maps a node
// key to the node's index, by open addressing with linear probing and Fibonacci hashing.
#pragma once

#include "flecsi_lite/topology/ntree/keys.hh"

#include <cassert>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace flecsi_lite::topology::ntree {

/// Open addressing rather than std::unordered_map: one flat array of (key, index) slots with no
/// allocation per node, a load factor at most 1/2 so that probes stay short, and cache-friendly
/// probing. Key 0 marks an empty slot, which no node can have (every key has its root bit).
class node_table {
public:
  static constexpr std::uint32_t npos = ~std::uint32_t{0};

  /// Maps keys[i] to i for every i < n. Precondition: the keys are distinct and valid.
  void build(const key_type* keys, std::size_t n) {
    assert(n < npos);
    std::size_t capacity = 16;
    while (capacity < 2 * n) capacity *= 2;
    shift_ = 64;
    for (std::size_t c = capacity; c > 1; c >>= 1) --shift_;
    slots_.assign(capacity, slot{});
    const std::size_t mask = capacity - 1;
    for (std::size_t i = 0; i < n; ++i) {
      assert(keys[i] != 0);
      std::size_t at = home(keys[i]);
      while (slots_[at].key != 0) {
        assert(slots_[at].key != keys[i]);
        at = (at + 1) & mask;
      }
      slots_[at] = slot{keys[i], static_cast<std::uint32_t>(i)};
    }
  }

  /// Index mapped to `key`, or npos when no node has that key.
  std::uint32_t find(key_type key) const {
    if (slots_.empty() || key == 0) return npos;
    const std::size_t mask = slots_.size() - 1;
    for (std::size_t at = home(key);; at = (at + 1) & mask) {
      if (slots_[at].key == key) return slots_[at].index;
      if (slots_[at].key == 0) return npos;
    }
  }

  std::size_t capacity() const { return slots_.size(); }
  std::size_t bytes() const { return slots_.size() * sizeof(slot); }

private:
  struct slot {
    key_type key = 0;
    std::uint32_t index = npos;
  };

  // Fibonacci hashing: the top bits of key * 2^64/phi spread nearby keys over the table.
  std::size_t home(key_type key) const {
    return static_cast<std::size_t>((key * 0x9e3779b97f4a7c15ull) >> shift_);
  }

  std::vector<slot> slots_;
  int shift_ = 64;
};

} // namespace flecsi_lite::topology::ntree
