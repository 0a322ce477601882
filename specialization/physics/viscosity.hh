// Pair terms of SPH dissipation: the Monaghan & Gingold (1983) artificial viscosity Pi_ab (seed
// eqs. 1.10-1.11) with the Balsara (1995) switch, the signal velocity of Springel (2005, eq. 13)
// that the Courant time step takes (time_step.hh), and the artificial conductivity of Price
// (2008, JCP 227, 10040).
//
// The pair functions are templates over the number type (a double, or a pack of lanes of
// physics/simd.hh): the SIMD force loop and the scalar code share one formula.
#pragma once

#include "specialization/numerics/simd.hh"

#include <Kokkos_Core.hpp>

#include <cmath>

namespace flecsph::physics {

/// alpha, beta and epsilon of (1.10)-(1.11); epsilon is a fraction of h^2 (mu's softening).
struct viscosity_parameters {
  double alpha = 1.0;
  double beta = 2.0;
  double epsilon = 0.01;
};

/// What the viscosity needs to know about one particle of a pair (or of one per lane).
/// `balsara` is that particle's Balsara factor (1 disables the switch).
template<class T>
struct basic_viscosity_particle {
  T rho;
  T c;  // sound speed
  T h;
  T balsara = 1.0;
};
using viscosity_particle = basic_viscosity_particle<double>;

/// mu_ab = h r_ab.v_ab / (r_ab^2 + epsilon h^2), (1.11), with r_ab = r_a - r_b, v_ab = v_a - v_b.
template<class T>
KOKKOS_INLINE_FUNCTION T viscosity_mu(T h, T r_dot_v, T r_squared, double epsilon) {
  return h * r_dot_v / (r_squared + epsilon * h * h);
}

/// Pi_ab of (1.10) for an approaching pair (r_ab.v_ab < 0; the caller selects), using the
/// arithmetic means of h, c and rho, times the mean Balsara factor of the pair. Symmetric in a
/// and b, as momentum and energy conservation require. With s = h r.v and d = r^2 + epsilon h^2
/// (mu = s / d), Pi = (-alpha c mu + beta mu^2) / rho = s (beta s - alpha c d) / (d^2 rho): one
/// division per pair instead of two (the force loop is bound by its divisions).
template<class T>
KOKKOS_INLINE_FUNCTION T approaching_pair_viscosity(const viscosity_parameters& parameters, T r_dot_v, T r_squared,
                                                    const basic_viscosity_particle<T>& a,
                                                    const basic_viscosity_particle<T>& b) {
  const T h = 0.5 * (a.h + b.h);
  const T c = 0.5 * (a.c + b.c);
  const T rho = 0.5 * (a.rho + b.rho);
  const T s = h * r_dot_v, d = r_squared + parameters.epsilon * h * h;
  const T pi_ab = s * (parameters.beta * s - parameters.alpha * c * d) / (d * d * rho);
  return pi_ab * 0.5 * (a.balsara + b.balsara);
}

/// Pi_ab of (1.10); zero for receding pairs (r_ab.v_ab >= 0).
KOKKOS_INLINE_FUNCTION double artificial_viscosity(const viscosity_parameters& parameters, double r_dot_v,
                                                   double r_squared, const viscosity_particle& a,
                                                   const viscosity_particle& b) {
  if (r_dot_v >= 0.0) return 0.0;
  return approaching_pair_viscosity(parameters, r_dot_v, r_squared, a, b);
}

/// Balsara (1995) factor f = |div v| / (|div v| + |curl v| + 1e-4 c/h), which turns the
/// viscosity off in shear flows; zero where the flow is not compressed or expanded.
KOKKOS_INLINE_FUNCTION double balsara_switch(double div_v, double curl_v_magnitude, double c, double h) {
  const double compression = std::fabs(div_v);
  if (compression == 0.0) return 0.0;
  return compression / (compression + std::fabs(curl_v_magnitude) + 1.0e-4 * c / h);
}

/// Signal velocity of a pair, v_sig = c_a + c_b - beta_signal w_ab with w_ab = v_ab.r_ab/|r_ab|
/// for approaching pairs (w_ab < 0) and v_sig = c_a + c_b otherwise (Springel 2005, MNRAS 364,
/// 1105, eq. 13, beta_signal = 3; Monaghan 1997).
template<class T>
KOKKOS_INLINE_FUNCTION T signal_velocity_of_approach(T c_a, T c_b, T w, double beta_signal) {
  return c_a + c_b - simd::select(w < 0.0, beta_signal * w, T(0.0));
}
template<class T>
KOKKOS_INLINE_FUNCTION T signal_velocity(T c_a, T c_b, T r_dot_v, T r, double beta_signal = 3.0) {
  // r = 0: 0/0 computed, not taken
  return signal_velocity_of_approach(c_a, c_b, simd::select(r > 0.0, r_dot_v / r, T(0.0)), beta_signal);
}

/// The same for r > 0 given 1/r (the force loop's pairs): no division.
template<class T>
KOKKOS_INLINE_FUNCTION T signal_velocity_from_inverse(T c_a, T c_b, T r_dot_v, T inverse_r, double beta_signal = 3.0) {
  return signal_velocity_of_approach(c_a, c_b, T(r_dot_v * inverse_r), beta_signal);
}

/// Signal speed of the artificial conductivity, v_sig^u = sqrt(|P_a - P_b| / rho_ab) with
/// rho_ab the mean density (Price 2008, eq. 29).
template<class T>
KOKKOS_INLINE_FUNCTION T conductivity_signal_velocity(T P_a, T P_b, T rho_a, T rho_b) {
  return simd::square_root(simd::absolute(P_a - P_b) / (0.5 * (rho_a + rho_b)));
}

/// Pair term of the artificial conductivity, to be multiplied by m_b and summed over b:
/// (du_a/dt)_cond = sum_b m_b alpha_u v_sig^u (u_a - u_b) / rho_ab * dW_ab/dr (Price 2008,
/// eq. 28). dW_dr is the radial derivative r_ab.grad_a W_ab / |r_ab| (negative; averaged over
/// h_a and h_b by the caller), so heat flows from the hotter to the colder particle and the
/// term is antisymmetric in a and b.
template<class T>
KOKKOS_INLINE_FUNCTION T artificial_conductivity(double alpha_u, T u_a, T u_b, T P_a, T P_b, T rho_a, T rho_b,
                                                 T dW_dr) {
  const T v_signal = conductivity_signal_velocity(P_a, P_b, rho_a, rho_b);
  return alpha_u * v_signal * (u_a - u_b) / (0.5 * (rho_a + rho_b)) * dW_dr;
}

}  // namespace flecsph::physics
