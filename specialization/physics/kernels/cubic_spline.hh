// The M4 cubic spline kernel (Monaghan & Lattanzio 1985; seed eqs. 1.12-1.13, with the typos of
// (1.12) corrected): f(q) = 1 - 3/2 q^2 + 3/4 q^3 on [0,1], 1/4 (2-q)^3 on [1,2], support 2h.
#pragma once

#include "specialization/physics/kernels/radial_kernel.hh"

namespace flecsph::physics {

struct cubic_spline_shape {
  static constexpr const char* name = "cubic_spline";

  /// sigma_D of the seed's (1.13): 2/3, 10/(7 pi), 1/pi.
  template<int D>
  static constexpr double normalization() {
    if constexpr (D == 1) return 2.0 / 3.0;
    else if constexpr (D == 2) return 10.0 / (7.0 * pi);
    else return 1.0 / pi;
  }

  template<int D>
  KOKKOS_INLINE_FUNCTION static double value(double q) {
    if (q < 1.0) return 1.0 - 1.5 * q * q + 0.75 * q * q * q;
    if (q < 2.0) return 0.25 * integer_power<3>(2.0 - q);
    return 0.0;
  }

  /// f'(q)/q: -3 + 9/4 q on [0,1], -3/4 (2-q)^2 / q on [1,2].
  template<int D>
  KOKKOS_INLINE_FUNCTION static double derivative_over_q(double q) {
    if (q < 1.0) return -3.0 + 2.25 * q;
    if (q < 2.0) return -0.75 * integer_power<2>(2.0 - q) / q;
    return 0.0;
  }
};

template<int D>
using cubic_spline = radial_kernel<cubic_spline_shape, D>;

} // namespace flecsph::physics
