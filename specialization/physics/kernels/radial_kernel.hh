// A smoothing kernel W(r, h) = sigma_D / h^D f(r/h) with compact support 2h, built from a
// dimensionless shape f(q); gives W, dW/dr, (1/r) dW/dr and dW/dh (Price 2012, JCP 231, 759, sec. 2).
#pragma once

#include "specialization/numerics/simd.hh"

#include <Kokkos_Core.hpp>

#include <type_traits>

namespace flecsph::physics {

/// x^N for a small non-negative compile-time N (the kernels' powers of h and of (1 - q)); x a
/// double or a pack of them (simd.hh).
template<int N, class T>
KOKKOS_INLINE_FUNCTION constexpr T integer_power(T x) {
  static_assert(N >= 0, "integer_power needs N >= 0");
  T result = 1.0;
  for (int i = 0; i < N; ++i) result *= x;
  return result;
}

inline constexpr double pi = 3.14159265358979323846;

/// Support radius of every kernel in units of h: particles interact when |r| < 2h.
inline constexpr double kernel_support = 2.0;

/// For shapes whose f'(q)/q is a polynomial in q (no division): q f'(q) = q^2 (f'(q)/q).
template<class Shape>
struct polynomial_derivative_forms {
  template<int D, class T>
  KOKKOS_INLINE_FUNCTION static T q_derivative(T q) {
    return q * q * Shape::template derivative_over_q<D>(q);
  }
  /// f'(q)/q given also 1/q, which a polynomial does not need.
  template<int D, class T>
  KOKKOS_INLINE_FUNCTION static T derivative_over_q_from(T q, T) {
    return Shape::template derivative_over_q<D>(q);
  }
};

/// piece(s, 1 - s) for s < 1 and 0 beyond, the form of the compactly supported shapes in
/// s = q/2: a branch for one double, a lane selection for a pack (each lane bitwise the double's
/// value).
template<class T, class Piece>
KOKKOS_INLINE_FUNCTION T inside_unit_support(T s, Piece&& piece) {
  if constexpr (std::is_same_v<T, double>) {
    if (s >= 1.0) return 0.0;
    return piece(s, 1.0 - s);
  } else {
    return simd::select(s < 1.0, piece(s, 1.0 - s), T(0.0));
  }
}

/// The kernel in dimension D built from `Shape`, which provides, for q = r/h:
///   normalization<D>()       sigma_D, so that the kernel integrates to 1 over R^D;
///   value<D>(q)              f(q), zero for q >= 2 (q a double or a pack, simd.hh);
///   derivative_over_q<D>(q)  f'(q)/q, finite at q = 0 (every shape here has f'(0) = 0);
///   q_derivative<D>(q)       q f'(q), with no division (for dW/dh in the density loop);
///   derivative_over_q_from<D>(q, 1/q)  f'(q)/q with no division, given 1/q (the force loop has
///                            1/r once per pair, and 1/q = h/r).
/// All functions are static: a kernel object is an empty tag, cheap to capture in a Kokkos lambda.
template<class Shape, int D>
struct radial_kernel {
  static_assert(D >= 1 && D <= 3, "kernels are defined for D = 1, 2, 3");
  using shape = Shape;
  static constexpr int dimension = D;
  static constexpr double sigma = Shape::template normalization<D>();

  /// True when a neighbour at distance r contributes: r < 2h.
  KOKKOS_INLINE_FUNCTION static bool in_support(double r, double h) { return r < kernel_support * h; }

  /// W(r, h).
  KOKKOS_INLINE_FUNCTION static double value(double r, double h) {
    const double inverse_h = 1.0 / h;
    return sigma * integer_power<D>(inverse_h) * Shape::template value<D>(r * inverse_h);
  }

  /// dW/dr at fixed h.
  KOKKOS_INLINE_FUNCTION static double radial_derivative(double r, double h) {
    const double inverse_h = 1.0 / h;
    const double q = r * inverse_h;
    return sigma * integer_power<D + 1>(inverse_h) * q * Shape::template derivative_over_q<D>(q);
  }

  /// (1/r) dW/dr, so that grad_a W_ab = (r_a - r_b) * gradient_factor; finite (not 0/0) at r = 0.
  KOKKOS_INLINE_FUNCTION static double gradient_factor(double r, double h) {
    const double inverse_h = 1.0 / h;
    return sigma * integer_power<D + 2>(inverse_h) * Shape::template derivative_over_q<D>(r * inverse_h);
  }

  /// dW/dh at fixed r = -(sigma / h^(D+1)) (D f(q) + q f'(q)), for the grad-h terms.
  KOKKOS_INLINE_FUNCTION static double h_derivative(double r, double h) {
    const double inverse_h = 1.0 / h;
    const double q = r * inverse_h;
    return -sigma * integer_power<D + 1>(inverse_h) *
           (D * Shape::template value<D>(q) + Shape::template q_derivative<D>(q));
  }
};

}  // namespace flecsph::physics
