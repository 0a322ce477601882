// Morton (Z-order) index of integer cell coordinates in 1, 2 and 3 dimensions: bit interleaving
// [Morton 1966] with the magic-mask bit spreading of Hacker's Delight (Warren 2012, sec. 7-2).
#pragma once

#include <array>
#include <cassert>
#include <cstdint>

namespace flecsi_lite::topology::ntree {

/// Spreads the low 21 bits of `v` (of each lane, for a vector Word) so that bit i moves to bit 3i.
template<class Word>
constexpr Word spread_bits_3(Word v) {
  v &= 0x1fffffull;
  v = (v | v << 32) & 0x1f00000000ffffull;
  v = (v | v << 16) & 0x1f0000ff0000ffull;
  v = (v | v << 8) & 0x100f00f00f00f00full;
  v = (v | v << 4) & 0x10c30c30c30c30c3ull;
  v = (v | v << 2) & 0x1249249249249249ull;
  return v;
}

/// Inverse of spread_bits_3: gathers bits 3i into bit i.
constexpr std::uint64_t compact_bits_3(std::uint64_t v) {
  v &= 0x1249249249249249ull;
  v = (v ^ (v >> 2)) & 0x10c30c30c30c30c3ull;
  v = (v ^ (v >> 4)) & 0x100f00f00f00f00full;
  v = (v ^ (v >> 8)) & 0x1f0000ff0000ffull;
  v = (v ^ (v >> 16)) & 0x1f00000000ffffull;
  v = (v ^ (v >> 32)) & 0x1fffffull;
  return v;
}

/// Spreads the low 32 bits of `v` (of each lane, for a vector Word) so that bit i moves to bit 2i.
template<class Word>
constexpr Word spread_bits_2(Word v) {
  v &= 0xffffffffull;
  v = (v | v << 16) & 0x0000ffff0000ffffull;
  v = (v | v << 8) & 0x00ff00ff00ff00ffull;
  v = (v | v << 4) & 0x0f0f0f0f0f0f0f0full;
  v = (v | v << 2) & 0x3333333333333333ull;
  v = (v | v << 1) & 0x5555555555555555ull;
  return v;
}

/// Inverse of spread_bits_2: gathers bits 2i into bit i.
constexpr std::uint64_t compact_bits_2(std::uint64_t v) {
  v &= 0x5555555555555555ull;
  v = (v ^ (v >> 1)) & 0x3333333333333333ull;
  v = (v ^ (v >> 2)) & 0x0f0f0f0f0f0f0f0full;
  v = (v ^ (v >> 4)) & 0x00ff00ff00ff00ffull;
  v = (v ^ (v >> 8)) & 0x0000ffff0000ffffull;
  v = (v ^ (v >> 16)) & 0x00000000ffffffffull;
  return v;
}

/// The interleaving of morton_index without its range checks: `Word` may be a vector of 64-bit
/// lanes (compute_keys), each lane interleaved alone.
template<int D, class Word>
constexpr Word interleave_bits(const std::array<Word, D>& cell) {
  if constexpr (D == 1)
    return cell[0];
  else if constexpr (D == 2)
    return spread_bits_2(cell[0]) << 1 | spread_bits_2(cell[1]);
  else
    return spread_bits_3(cell[0]) << 2 | spread_bits_3(cell[1]) << 1 | spread_bits_3(cell[2]);
}

/// Morton index of a cell: bit j of axis k goes to bit D*j + (D-1-k), so axis 0 is the most
/// significant bit of every D-bit digit (the convention of Skilling's Hilbert transpose).
/// @param[in] cell coordinates, each below 2^(63/D).
template<int D>
constexpr std::uint64_t morton_index(const std::array<std::uint64_t, D>& cell) {
  static_assert(D >= 1 && D <= 3, "ntree supports 1, 2 and 3 dimensions");
  if constexpr (D == 1)
    assert(cell[0] < (1ull << 63));
  else if constexpr (D == 2)
    assert(cell[0] < (1ull << 31) && cell[1] < (1ull << 31));
  else
    assert(cell[0] < (1ull << 21) && cell[1] < (1ull << 21) && cell[2] < (1ull << 21));
  return interleave_bits<D>(cell);
}

/// Inverse of morton_index.
template<int D>
constexpr std::array<std::uint64_t, D> morton_cell(std::uint64_t index) {
  static_assert(D >= 1 && D <= 3, "ntree supports 1, 2 and 3 dimensions");
  if constexpr (D == 1) {
    return {index};
  } else if constexpr (D == 2) {
    return {compact_bits_2(index >> 1), compact_bits_2(index)};
  } else {
    return {compact_bits_3(index >> 2), compact_bits_3(index >> 1), compact_bits_3(index)};
  }
}

}  // namespace flecsi_lite::topology::ntree
