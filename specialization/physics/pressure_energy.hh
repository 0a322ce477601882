// The per-particle factors of pressure-energy SPH (Hopkins 2013, MNRAS 428, 2840, sec. 2.4 and
// his eqs. for x_i = (gamma-1) m_i u_i, y_i = P_bar_i), with h set by the mass density as the
// density-energy equations do (h = eta (m / rho)^(1/D)). For a pair (a, b), q = (gamma-1) u,
//   dv_a/dt = -sum_b m_b [A_a (q_b - g_a) grad W_ab(h_a) + A_b (q_a - g_b) grad W_ab(h_b)]
//   du_a/dt =  sum_b m_b A_a (q_b - g_a) v_ab . grad W_ab(h_a),
// with A = q / P_bar and g the grad-h term below: Hopkins' (gamma-1)^2 m_b u_a u_b f_ab / P_bar_a
// with f_ab = 1 - g_a / q_b (his f_ab divides by m_b u_b, h following the number density; with
// the mass density the m_b cancels).
#pragma once

#include <Kokkos_Core.hpp>

#include <cmath>

namespace flecsph::physics {

/// A = (gamma-1) u / P_bar, the factor of the pair terms; 0 where P_bar is 0 (no hot neighbour:
/// the particle then exerts no pressure force, as P_bar = 0 says).
KOKKOS_INLINE_FUNCTION double pressure_energy_term(double gamma_minus_one, double u, double P_bar) {
  return P_bar > 0.0 ? gamma_minus_one * u / P_bar : 0.0;
}

/// g = h dP_bar/dh / (D rho Omega): the variation of P_bar with h through the h-rho relation
/// (dh/drho = -h / (D rho), Omega the density's grad-h factor); 0 for a fixed h.
template<int D>
KOKKOS_INLINE_FUNCTION double pressure_energy_grad_h(double h, double dP_bar_dh, double rho, double omega) {
  return h * dP_bar_dh / (D * rho * omega);
}

/// c = sqrt(gamma P_bar / rho): the sound speed with the smoothed pressure (SWIFT's pressure-energy).
KOKKOS_INLINE_FUNCTION double pressure_energy_sound_speed(double gamma, double P_bar, double rho) {
  return std::sqrt(gamma * P_bar / rho);
}

}  // namespace flecsph::physics
