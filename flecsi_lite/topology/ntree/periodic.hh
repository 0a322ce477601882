// Periodic boundaries for the ntree searches: a domain box periodic along any subset of its axes,
// and the image shifts (-L, 0, +L per periodic axis) under which sources are seen (minimum image).
#pragma once

#include "flecsi_lite/topology/ntree/space.hh"

#include <algorithm>
#include <array>
#include <cassert>
#include <cstdint>
#include <limits>

namespace flecsi_lite::topology::ntree {

/// Image shifts are named by a code: digit k (base 3) of the code says the shift along axis k is
/// -L_k (0), none (1) or +L_k (2). A source particle b seen under shift code s sits at
/// x_b + shift(s), so the separation the physics uses is r_ab = x_a - (x_b + shift(s)).
using shift_code = std::uint8_t;

template<int D>
constexpr int shift_code_count = D == 1   ? 3
                                 : D == 2 ? 9
                                          : 27;

/// The code of the zero shift (digit 1 on every axis).
template<int D>
constexpr shift_code zero_shift = D == 1   ? 1
                                  : D == 2 ? 4
                                           : 13;

/// The box in which particles live, periodic along the axes flagged in `periodic` with period
/// hi - lo. Particles must lie inside the box along periodic axes (the physics wraps them).
template<int D>
struct domain {
  box<D> bounds{};
  std::array<bool, D> periodic{};

  /// A domain with no periodic axis: searches see only the particles themselves.
  static domain open() {
    domain result;
    result.bounds.lo.fill(0);
    result.bounds.hi.fill(1);
    return result;
  }

  bool any_periodic() const {
    for (int k = 0; k < D; ++k)
      if (periodic[k]) return true;
    return false;
  }

  double period(int axis) const { return bounds.hi[axis] - bounds.lo[axis]; }

  /// Smallest period among the periodic axes (infinite when none is periodic).
  double min_period() const {
    double result = std::numeric_limits<double>::infinity();
    for (int k = 0; k < D; ++k)
      if (periodic[k]) result = std::min(result, period(k));
    return result;
  }

  /// The displacement named by `code`. Precondition: non-zero digits only on periodic axes.
  point<D> shift(shift_code code) const {
    point<D> s;
    for (int k = 0; k < D; ++k) {
      const int digit = code % 3;
      code = static_cast<shift_code>(code / 3);
      assert(digit == 1 || periodic[k]);
      s[k] = digit == 1 ? 0.0 : digit == 0 ? -period(k) : period(k);
    }
    return s;
  }

  /// shift(code) for every code (zero on the non-periodic axes), for walks to index by code.
  std::array<point<D>, shift_code_count<D>> shift_table() const {
    std::array<point<D>, shift_code_count<D>> table{};
    const std::uint32_t allowed = allowed_shifts();
    for (int code = 0; code < shift_code_count<D>; ++code)
      if (allowed >> code & 1) table[code] = shift(static_cast<shift_code>(code));
    return table;
  }

  /// Bit s set for every shift code s allowed by the periodic axes (only zero_shift if none).
  std::uint32_t allowed_shifts() const {
    std::uint32_t mask = 0;
    for (int code = 0; code < shift_code_count<D>; ++code) {
      bool allowed = true;
      int rest = code;
      for (int k = 0; k < D; ++k, rest /= 3)
        if (rest % 3 != 1 && !periodic[k]) allowed = false;
      if (allowed) mask |= std::uint32_t{1} << code;
    }
    return mask;
  }
};

}  // namespace flecsi_lite::topology::ntree
