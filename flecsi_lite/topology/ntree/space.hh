// Geometry of the ntree topology: points, axis-aligned boxes, normalisation of a position into a
// box, and the squared point/box distances with which the tree walks prune (Barnes & Hut 1986).
#pragma once

#include <algorithm>
#include <array>
#include <cassert>
#include <limits>

#if defined(__SSE2__)
#include <emmintrin.h>
#endif

namespace flecsi_lite::topology::ntree {

/// A position (or displacement) in D dimensions.
template<int D>
using point = std::array<double, D>;

/// A closed axis-aligned box [lo, hi]. The empty box has lo = +inf and hi = -inf, so that
/// extending it by a point gives that point's degenerate box.
template<int D>
struct box {
  static_assert(D >= 1 && D <= 3, "ntree supports 1, 2 and 3 dimensions");

  point<D> lo;
  point<D> hi;

  static box empty() {
    box result;
    result.lo.fill(std::numeric_limits<double>::infinity());
    result.hi.fill(-std::numeric_limits<double>::infinity());
    return result;
  }

  bool is_empty() const {
    for (int k = 0; k < D; ++k)
      if (!(lo[k] <= hi[k])) return true;
    return false;
  }

  void extend(const point<D>& x) {
    for (int k = 0; k < D; ++k) {
      lo[k] = std::min(lo[k], x[k]);
      hi[k] = std::max(hi[k], x[k]);
    }
  }

  void extend(const box& other) {
    for (int k = 0; k < D; ++k) {
      lo[k] = std::min(lo[k], other.lo[k]);
      hi[k] = std::max(hi[k], other.hi[k]);
    }
  }

  bool contains(const point<D>& x) const {
    for (int k = 0; k < D; ++k)
      if (x[k] < lo[k] || x[k] > hi[k]) return false;
    return true;
  }

  bool intersects(const box& other) const {
    for (int k = 0; k < D; ++k)
      if (other.hi[k] < lo[k] || other.lo[k] > hi[k]) return false;
    return true;
  }

  /// The box translated by `shift` (used for periodic images).
  box shifted(const point<D>& shift) const {
    box result;
    for (int k = 0; k < D; ++k) {
      result.lo[k] = lo[k] + shift[k];
      result.hi[k] = hi[k] + shift[k];
    }
    return result;
  }

  point<D> centre() const {
    point<D> c;
    for (int k = 0; k < D; ++k) c[k] = 0.5 * (lo[k] + hi[k]);
    return c;
  }

  /// Largest side length; the "size" of a node in the Barnes-Hut opening criterion.
  double max_extent() const {
    double size = 0;
    for (int k = 0; k < D; ++k) size = std::max(size, hi[k] - lo[k]);
    return size;
  }

  friend bool operator==(const box& a, const box& b) { return a.lo == b.lo && a.hi == b.hi; }
  friend bool operator!=(const box& a, const box& b) { return !(a == b); }
};

/// Position of `x` in box `b` scaled to [0, 1] per axis (not clamped: points outside map
/// outside). Precondition: `b` has positive extent on every axis.
template<int D>
point<D> normalize(const box<D>& b, const point<D>& x) {
  point<D> u;
  for (int k = 0; k < D; ++k) {
    assert(b.hi[k] > b.lo[k]);
    u[k] = (x[k] - b.lo[k]) / (b.hi[k] - b.lo[k]);
  }
  return u;
}

/// max(0, a, b), the gap along one axis between a point or box and a box. On x86 it is forced
/// onto the max instruction: compilers otherwise branch on the sign, a branch that tree walks
/// mispredict half of the time.
inline double positive_max(double a, double b) {
#if defined(__SSE2__)
  return _mm_cvtsd_f64(_mm_max_sd(_mm_max_sd(_mm_set_sd(a), _mm_set_sd(b)), _mm_setzero_pd()));
#else
  return std::max(0.0, std::max(a, b));
#endif
}

/// |a - b|^2, summed axis by axis. Every pair criterion of the searches uses this one function.
template<int D>
inline double distance_squared(const point<D>& a, const point<D>& b) {
  double r2 = 0;
  for (int k = 0; k < D; ++k) {
    const double d = a[k] - b[k];
    r2 += d * d;
  }
  return r2;
}

/// Squared distance from `x` to the nearest point of `b` (0 inside). Computed with the same
/// rounding steps as distance_squared, so for any y in `b` it never exceeds
/// distance_squared(x, y) in floating point: pruning on it is exact, not approximate.
template<int D>
inline double distance_squared(const box<D>& b, const point<D>& x) {
  double r2 = 0;
  for (int k = 0; k < D; ++k) {
    const double gap = positive_max(b.lo[k] - x[k], x[k] - b.hi[k]);
    r2 += gap * gap;
  }
  return r2;
}

/// Squared distance between the nearest points of two boxes (0 when they intersect); never
/// exceeds the floating-point distance_squared of any pair of points taken one from each box.
template<int D>
inline double distance_squared(const box<D>& a, const box<D>& b) {
  double r2 = 0;
  for (int k = 0; k < D; ++k) {
    const double gap = positive_max(a.lo[k] - b.hi[k], b.lo[k] - a.hi[k]);
    r2 += gap * gap;
  }
  return r2;
}

}  // namespace flecsi_lite::topology::ntree
