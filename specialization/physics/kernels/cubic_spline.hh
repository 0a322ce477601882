// The M4 cubic spline kernel (Monaghan & Lattanzio 1985; seed eqs. 1.12-1.13, with the typos of
// (1.12) corrected): f(q) = 1 - 3/2 q^2 + 3/4 q^3 on [0,1], 1/4 (2-q)^3 on [1,2], support 2h.
#pragma once

#include "specialization/physics/kernels/radial_kernel.hh"

#include <type_traits>

namespace flecsph::physics {

struct cubic_spline_shape {
  static constexpr const char* name = "cubic_spline";

  /// sigma_D of the seed's (1.13): 2/3, 10/(7 pi), 1/pi.
  template<int D>
  static constexpr double normalization() {
    if constexpr (D == 1)
      return 2.0 / 3.0;
    else if constexpr (D == 2)
      return 10.0 / (7.0 * pi);
    else
      return 1.0 / pi;
  }

  // The density loop evaluates f and q f'(q) for neighbours in random order of q: there, with
  // a = max(2 - q, 0) and b = max(1 - q, 0) (Monaghan 1992, ARA&A 30, 543),
  //   f(q) = (a^3 - 4 b^3) / 4  and  q f'(q) = -3/4 q (a + 2b)(a - 2b),  a - 2b = min(q, a),
  // need no branch on q and no division by it.
  template<int D, class T>
  KOKKOS_INLINE_FUNCTION static T value(T q) {
    const T a = outer_part(q), b = inner_part(q);
    return 0.25 * (a * a * a - 4.0 * (b * b * b));
  }

  /// q f'(q): -3 q^2 + 9/4 q^3 on [0,1], -3/4 q (2-q)^2 on [1,2].
  template<int D, class T>
  KOKKOS_INLINE_FUNCTION static T q_derivative(T q) {
    const T a = outer_part(q), b = inner_part(q);
    return -0.75 * q * (a + 2.0 * b) * simd::minimum(q, a);
  }

  /// f'(q)/q: -3 + 9/4 q on [0,1], -3/4 (2-q)^2 / q on [1,2]; for a pack both pieces are
  /// computed and each lane takes its own (the same bits as the branches).
  template<int D, class T>
  KOKKOS_INLINE_FUNCTION static T derivative_over_q(T q) {
    return derivative_over_q_pieces(q, [](T p) -> T { return -0.75 * integer_power<2>(2.0 - p) / p; });
  }

  /// The same from q and 1/q, with no division: -3/4 (2-q)^2 (1/q) on [1,2].
  template<int D, class T>
  KOKKOS_INLINE_FUNCTION static T derivative_over_q_from(T q, T inverse_q) {
    return derivative_over_q_pieces(q, [inverse_q](T p) -> T { return -0.75 * integer_power<2>(2.0 - p) * inverse_q; });
  }

 private:
  /// f'(q)/q with the piece on [1,2] given: a branch for one double, a lane selection for a pack.
  template<class T, class Outer>
  KOKKOS_INLINE_FUNCTION static T derivative_over_q_pieces(T q, Outer&& outer) {
    if constexpr (std::is_same_v<T, double>) {
      if (q < 1.0) return -3.0 + 2.25 * q;
      if (q < 2.0) return outer(q);
      return 0.0;
    } else {
      return simd::select(q < 1.0, -3.0 + 2.25 * q, simd::select(q < 2.0, outer(q), T(0.0)));
    }
  }
  // max(x, 0) as (x + |x|) / 2, exact: a form compilers do not turn back into a branch.
  template<class T>
  KOKKOS_INLINE_FUNCTION static T positive_part(T x) {
    return 0.5 * (x + simd::absolute(x));
  }
  template<class T>
  KOKKOS_INLINE_FUNCTION static T outer_part(T q) {
    return positive_part(2.0 - q);
  }
  template<class T>
  KOKKOS_INLINE_FUNCTION static T inner_part(T q) {
    return positive_part(1.0 - q);
  }
};

template<int D>
using cubic_spline = radial_kernel<cubic_spline_shape, D>;

}  // namespace flecsph::physics
