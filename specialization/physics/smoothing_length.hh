// The h-rho relation h = eta (m/rho)^(1/D), one Newton-Raphson step of the adaptive smoothing
// length, and the grad-h factor Omega (Springel & Hernquist 2002; Price 2012, JCP 231, 759, sec. 3).
#pragma once

#include "specialization/physics/kernels/radial_kernel.hh"

#include <Kokkos_Core.hpp>

#include <cmath>

namespace flecsph::physics {

/// x^(1/D).
template<int D>
KOKKOS_INLINE_FUNCTION double dimension_root(double x) {
  static_assert(D >= 1 && D <= 3, "D = 1, 2, 3");
  if constexpr (D == 1)
    return x;
  else if constexpr (D == 2)
    return std::sqrt(x);
  else
    return std::cbrt(x);
}

/// h = eta (m / rho)^(1/D).
template<int D>
KOKKOS_INLINE_FUNCTION double smoothing_length_from_density(double m, double rho, double eta) {
  return eta * dimension_root<D>(m / rho);
}

/// rho_h = m (eta / h)^D, the density that the h-rho relation assigns to h.
template<int D>
KOKKOS_INLINE_FUNCTION double density_from_smoothing_length(double m, double h, double eta) {
  return m * integer_power<D>(eta / h);
}

/// Relative residual (rho_sum - rho_h) / rho_h of the h-rho relation; iterate until it is small.
template<int D>
KOKKOS_INLINE_FUNCTION double smoothing_length_residual(double h, double rho_sum, double m, double eta) {
  const double rho_h = density_from_smoothing_length<D>(m, h, eta);
  return (rho_sum - rho_h) / rho_h;
}

/// One Newton-Raphson step on f(h) = rho_sum(h) - m (eta/h)^D, where rho_sum = sum_b m_b W_ab(h)
/// and drho_sum_dh = sum_b m_b dW_ab/dh, both evaluated at the current h:
///   f'(h) = drho_sum_dh + D rho_h / h,   h_new = h - f / f'.
/// When f' <= 0 or the step leaves [h/2, 2h] (far from the root, where Newton is unreliable),
/// falls back to the fixed-point update h = eta (m / rho_sum)^(1/D), also limited to [h/2, 2h].
template<int D>
KOKKOS_INLINE_FUNCTION double smoothing_length_newton_step(double h, double rho_sum, double drho_sum_dh, double m,
                                                           double eta) {
  const double rho_h = density_from_smoothing_length<D>(m, h, eta);
  const double f = rho_sum - rho_h;
  const double derivative = drho_sum_dh + D * rho_h / h;
  if (derivative > 0.0) {
    const double h_new = h - f / derivative;
    if (h_new >= 0.5 * h && h_new <= 2.0 * h) return h_new;
  }
  const double fixed_point = smoothing_length_from_density<D>(m, rho_sum, eta);
  return fixed_point < 0.5 * h ? 0.5 * h : (fixed_point > 2.0 * h ? 2.0 * h : fixed_point);
}

/// Omega = 1 - (dh/drho) sum_b m_b dW_ab/dh = 1 + h / (D rho) sum_b m_b dW_ab/dh, using
/// dh/drho = -h / (D rho) from the h-rho relation. The grad-h equations of motion divide the
/// pressure terms by it (Price 2012, eqs. 28-30).
template<int D>
KOKKOS_INLINE_FUNCTION double grad_h_omega(double h, double rho, double drho_sum_dh) {
  return 1.0 + h / (D * rho) * drho_sum_dh;
}

}  // namespace flecsph::physics
