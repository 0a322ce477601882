// Hilbert index of integer cell coordinates in 2 and 3 dimensions (1D: the identity, as Morton),
// by the transpose algorithm of J. Skilling, "Programming the Hilbert curve", AIP Conf. Proc.
// 707, 381 (2004): coordinates -> "transposed" Hilbert index -> bit interleaving.
#pragma once

#include "flecsi_lite/topology/ntree/morton.hh"

#include <array>
#include <cassert>
#include <cstdint>

namespace flecsi_lite::topology::ntree {

/// Skilling's AxestoTranspose: turns `bits`-bit coordinates into the transposed Hilbert index
/// (bit j of the index's digit at each level spread over the axes). Bit j of the result depends
/// only on bits >= j of the input, which makes Hilbert prefixes hierarchical cell keys.
template<int D>
constexpr std::array<std::uint64_t, D> hilbert_transpose(std::array<std::uint64_t, D> x,
                                                         int bits) {
  assert(bits >= 0 && bits <= 63 / D);
  if (bits == 0) return x;
  const std::uint64_t top = std::uint64_t{1} << (bits - 1);
  // Inverse undo of the excess work: rotate/reflect lower bits by each higher bit.
  for (std::uint64_t q = top; q > 1; q >>= 1) {
    const std::uint64_t p = q - 1;
    for (int i = 0; i < D; ++i) {
      if (x[i] & q) {
        x[0] ^= p; // invert
      } else {
        const std::uint64_t t = (x[0] ^ x[i]) & p; // exchange
        x[0] ^= t;
        x[i] ^= t;
      }
    }
  }
  // Gray encode.
  for (int i = 1; i < D; ++i) x[i] ^= x[i - 1];
  std::uint64_t t = 0;
  for (std::uint64_t q = top; q > 1; q >>= 1)
    if (x[D - 1] & q) t ^= q - 1;
  for (int i = 0; i < D; ++i) x[i] ^= t;
  return x;
}

/// Skilling's TransposetoAxes: inverse of hilbert_transpose.
template<int D>
constexpr std::array<std::uint64_t, D> hilbert_untranspose(std::array<std::uint64_t, D> x,
                                                           int bits) {
  assert(bits >= 0 && bits <= 63 / D);
  if (bits == 0) return x;
  const std::uint64_t end = std::uint64_t{2} << (bits - 1);
  // Gray decode by H ^ (H / 2).
  const std::uint64_t t = x[D - 1] >> 1;
  for (int i = D - 1; i > 0; --i) x[i] ^= x[i - 1];
  x[0] ^= t;
  // Undo the excess work.
  for (std::uint64_t q = 2; q != end; q <<= 1) {
    const std::uint64_t p = q - 1;
    for (int i = D - 1; i >= 0; --i) {
      if (x[i] & q) {
        x[0] ^= p;
      } else {
        const std::uint64_t s = (x[0] ^ x[i]) & p;
        x[0] ^= s;
        x[i] ^= s;
      }
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

} // namespace flecsi_lite::topology::ntree
