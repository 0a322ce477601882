// Compact copy of a tree node for the neighbour-search walks: the bounding box rounded outward to
// single precision and the largest h rounded up, so that a node takes 44 bytes in 3D (not 112)
// while pruning on it stays conservative, hence the searches exact.
#pragma once

#include "flecsi_lite/topology/ntree/space.hh"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>

namespace flecsi_lite::topology::ntree {

/// Nearest float not above `value`.
inline float float_below(double value) {
  float result = static_cast<float>(value);
  if (static_cast<double>(result) > value) result = std::nextafter(result, -std::numeric_limits<float>::infinity());
  return result;
}

/// Nearest float not below `value`.
inline float float_above(double value) {
  float result = static_cast<float>(value);
  if (static_cast<double>(result) < value) result = std::nextafter(result, std::numeric_limits<float>::infinity());
  return result;
}

/// The walk's view of a node: its box contains the node's exact box, and h_max bounds the
/// node's smoothing lengths from above, so the squared distance to this box never exceeds the
/// (floating-point) distance to any particle of the node, and reaches computed from h_max are
/// never shorter than a particle's.
template<int D>
struct search_node {
  std::array<float, D> lo;
  std::array<float, D> hi;
  float h_max;
  std::uint32_t begin;
  std::uint32_t end;
  std::uint32_t first_child;
  std::uint32_t child_count;  ///< 0 for a leaf

  bool is_leaf() const { return child_count == 0; }

  /// Squared distance from the targets' box to this box translated by `shift`. The gap is
  /// formed from the same quantities in the same order as distance_squared(box, box), with
  /// each bound moved outward, so it never exceeds the distance between members.
  template<bool Shifted>
  double distance_squared_to(const box<D>& targets, const point<D>& shift) const {
    double r2 = 0;
    for (int k = 0; k < D; ++k) {
      double low = static_cast<double>(lo[k]);
      double high = static_cast<double>(hi[k]);
      if constexpr (Shifted) {
        low += shift[k];
        high += shift[k];
      }
      const double gap = positive_max(targets.lo[k] - high, low - targets.hi[k]);
      r2 += gap * gap;
    }
    return r2;
  }

  /// Squared distance from point `x` to this box translated by `shift`.
  template<bool Shifted>
  double distance_squared_to(const point<D>& x, const point<D>& shift) const {
    double r2 = 0;
    for (int k = 0; k < D; ++k) {
      double low = static_cast<double>(lo[k]);
      double high = static_cast<double>(hi[k]);
      if constexpr (Shifted) {
        low += shift[k];
        high += shift[k];
      }
      const double gap = positive_max(low - x[k], x[k] - high);
      r2 += gap * gap;
    }
    return r2;
  }
};

}  // namespace flecsi_lite::topology::ntree
