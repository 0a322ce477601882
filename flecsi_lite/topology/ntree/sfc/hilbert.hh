// Hilbert index of integer cell coordinates in 2 and 3 dimensions (1D: the identity, as Morton),
// by the transpose algorithm of J. Skilling, "Programming the Hilbert curve", AIP Conf. Proc.
// 707, 381 (2004): coordinates -> "transposed" Hilbert index -> bit interleaving.
#pragma once

#include "flecsi_lite/topology/ntree/sfc/morton.hh"

#include <array>
#include <cassert>
#include <cstdint>

namespace flecsi_lite::topology::ntree {

/// Skilling's AxestoTranspose: turns `bits`-bit coordinates into the transposed Hilbert index
/// (bit j of the index's digit at each level spread over the axes). Bit j of the result depends
/// only on bits >= j of the input, which makes Hilbert prefixes hierarchical cell keys. `Word`
/// may be a vector of 64-bit lanes (compute_keys): the same integer operations on each lane.
template<int D, class Word = std::uint64_t>
constexpr std::array<Word, D> hilbert_transpose(std::array<Word, D> x, int bits) {
  assert(bits >= 0 && bits <= 63 / D);
  if (bits == 0) return x;
  // Inverse undo of the excess work: rotate/reflect lower bits by each higher bit. Written
  // without branches (masks select "invert" or "exchange"): the bits are data, not patterns.
  for (int level = bits - 1; level > 0; --level) {
    const std::uint64_t low = (std::uint64_t{1} << level) - 1;
    for (int i = 0; i < D; ++i) {
      const Word set = 0 - (x[i] >> level & 1);
      const Word exchange = (x[0] ^ x[i]) & low & ~set;
      x[0] ^= (low & set) | exchange;  // invert when the bit is set, else exchange
      x[i] ^= exchange;
    }
  }
  // Gray encode.
  for (int i = 1; i < D; ++i) x[i] ^= x[i - 1];
  Word t{};
  for (int level = bits - 1; level > 0; --level) t ^= ((std::uint64_t{1} << level) - 1) & (0 - (x[D - 1] >> level & 1));
  for (int i = 0; i < D; ++i) x[i] ^= t;
  return x;
}

/// Skilling's TransposetoAxes: inverse of hilbert_transpose.
template<int D>
constexpr std::array<std::uint64_t, D> hilbert_untranspose(std::array<std::uint64_t, D> x, int bits) {
  assert(bits >= 0 && bits <= 63 / D);
  if (bits == 0) return x;
  // Gray decode by H ^ (H / 2).
  const std::uint64_t t = x[D - 1] >> 1;
  for (int i = D - 1; i > 0; --i) x[i] ^= x[i - 1];
  x[0] ^= t;
  // Undo the excess work, lowest bit first.
  for (int level = 1; level < bits; ++level) {
    const std::uint64_t low = (std::uint64_t{1} << level) - 1;
    for (int i = D - 1; i >= 0; --i) {
      const std::uint64_t set = 0 - (x[i] >> level & 1);
      const std::uint64_t exchange = (x[0] ^ x[i]) & low & ~set;
      x[0] ^= (low & set) | exchange;
      x[i] ^= exchange;
    }
  }
  return x;
}

/// Position along the Hilbert curve of order `bits` of the cell with coordinates `cell`
/// (each below 2^bits). Consecutive indices are face-neighbour cells.
template<int D>
constexpr std::uint64_t hilbert_index(const std::array<std::uint64_t, D>& cell, int bits) {
  if constexpr (D == 1) {
    assert(bits >= 0 && bits <= 63);
    return cell[0];
  } else {
    return morton_index<D>(hilbert_transpose<D>(cell, bits));
  }
}

/// Inverse of hilbert_index.
template<int D>
constexpr std::array<std::uint64_t, D> hilbert_cell(std::uint64_t index, int bits) {
  if constexpr (D == 1) {
    return {index};
  } else {
    return hilbert_untranspose<D>(morton_cell<D>(index), bits);
  }
}

}  // namespace flecsi_lite::topology::ntree
