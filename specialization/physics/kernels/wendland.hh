// Wendland C2, C4 and C6 kernels (Wendland 1995; Dehnen & Aly 2012, MNRAS 425, 1068, Table 1,
// including their 1D functions), rescaled from support radius H to 2h: s = r/H = q/2.
#pragma once

#include "specialization/physics/kernels/radial_kernel.hh"

namespace flecsph::physics {

// Each shape evaluates Dehnen & Aly's psi(s) on s = q/2. With W = N_D / H^D psi(r/H) and H = 2h,
// sigma_D = N_D / 2^D, and (1/q) d psi(q/2)/dq = (psi'(s)/s) / 4. D = 1 uses the 1D Wendland
// function of the same smoothness; D = 2 and 3 share one function with different N_D.

struct wendland_c2_shape : polynomial_derivative_forms<wendland_c2_shape> {
  static constexpr const char* name = "wendland_c2";

  template<int D>
  static constexpr double normalization() {
    if constexpr (D == 1)
      return (5.0 / 4.0) / 2.0;
    else if constexpr (D == 2)
      return (7.0 / pi) / 4.0;
    else
      return (21.0 / (2.0 * pi)) / 8.0;
  }

  template<int D, class T>
  KOKKOS_INLINE_FUNCTION static T value(T q) {
    return inside_unit_support(0.5 * q, [](T s, T t) -> T {
      if constexpr (D == 1)
        return integer_power<3>(t) * (1.0 + 3.0 * s);
      else
        return integer_power<4>(t) * (1.0 + 4.0 * s);
    });
  }

  template<int D, class T>
  KOKKOS_INLINE_FUNCTION static T derivative_over_q(T q) {
    return inside_unit_support(0.5 * q, [](T, T t) -> T {
      if constexpr (D == 1)
        return 0.25 * (-12.0 * integer_power<2>(t));
      else
        return 0.25 * (-20.0 * integer_power<3>(t));
    });
  }
};

struct wendland_c4_shape : polynomial_derivative_forms<wendland_c4_shape> {
  static constexpr const char* name = "wendland_c4";

  template<int D>
  static constexpr double normalization() {
    if constexpr (D == 1)
      return (3.0 / 2.0) / 2.0;
    else if constexpr (D == 2)
      return (9.0 / pi) / 4.0;
    else
      return (495.0 / (32.0 * pi)) / 8.0;
  }

  template<int D, class T>
  KOKKOS_INLINE_FUNCTION static T value(T q) {
    return inside_unit_support(0.5 * q, [](T s, T t) -> T {
      if constexpr (D == 1)
        return integer_power<5>(t) * (1.0 + s * (5.0 + 8.0 * s));
      else
        return integer_power<6>(t) * (1.0 + s * (6.0 + (35.0 / 3.0) * s));
    });
  }

  template<int D, class T>
  KOKKOS_INLINE_FUNCTION static T derivative_over_q(T q) {
    return inside_unit_support(0.5 * q, [](T s, T t) -> T {
      if constexpr (D == 1)
        return 0.25 * (-14.0 * integer_power<4>(t) * (1.0 + 4.0 * s));
      else
        return 0.25 * (-(56.0 / 3.0) * integer_power<5>(t) * (1.0 + 5.0 * s));
    });
  }
};

struct wendland_c6_shape : polynomial_derivative_forms<wendland_c6_shape> {
  static constexpr const char* name = "wendland_c6";

  template<int D>
  static constexpr double normalization() {
    if constexpr (D == 1)
      return (55.0 / 32.0) / 2.0;
    else if constexpr (D == 2)
      return (78.0 / (7.0 * pi)) / 4.0;
    else
      return (1365.0 / (64.0 * pi)) / 8.0;
  }

  template<int D, class T>
  KOKKOS_INLINE_FUNCTION static T value(T q) {
    return inside_unit_support(0.5 * q, [](T s, T t) -> T {
      if constexpr (D == 1)
        return integer_power<7>(t) * (1.0 + s * (7.0 + s * (19.0 + 21.0 * s)));
      else
        return integer_power<8>(t) * (1.0 + s * (8.0 + s * (25.0 + 32.0 * s)));
    });
  }

  template<int D, class T>
  KOKKOS_INLINE_FUNCTION static T derivative_over_q(T q) {
    return inside_unit_support(0.5 * q, [](T s, T t) -> T {
      if constexpr (D == 1)
        return 0.25 * (-6.0 * integer_power<6>(t) * (3.0 + s * (18.0 + 35.0 * s)));
      else
        return 0.25 * (-22.0 * integer_power<7>(t) * (1.0 + s * (7.0 + 16.0 * s)));
    });
  }
};

template<int D>
using wendland_c2 = radial_kernel<wendland_c2_shape, D>;
template<int D>
using wendland_c4 = radial_kernel<wendland_c4_shape, D>;
template<int D>
using wendland_c6 = radial_kernel<wendland_c6_shape, D>;

}  // namespace flecsph::physics
