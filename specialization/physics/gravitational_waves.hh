// Gravitational-wave strain of a Newtonian source in the quadrupole approximation (Einstein 1918;
// Maggiore 2008, "Gravitational Waves" vol. 1, eqs. 3.72 and 3.76): h_ij = (2 G / (c^4 d)) Ï_ij^TT,
// with Ï_ij = sum m (2 v_i v_j + x_i a_j + a_i x_j) from positions, velocities and accelerations.
//
//   symmetric_tensor rate{};                                // Ï_ij, summed particle by particle
//   for (...) { const auto term = quadrupole_second_derivative(m, x, v, a); for (k...) rate[k] += term[k]; }
//   const polarisations h = strain_on_z_axis(rate, G, c, d);         // h.plus, h.cross
#pragma once

#include <array>
#include <cmath>

namespace flecsph::physics {

/// Ï_ij of one particle about the origin: m (2 v_i v_j + x_i a_j + a_i x_j), the exact second time
/// derivative of I_ij = m x_i x_j (no finite differences in time). Indices in the order xx, yy, zz,
/// xy, xz, yz. The trace is not removed: the strain on an axis below does not see it.
using symmetric_tensor = std::array<double, 6>;

inline symmetric_tensor quadrupole_second_derivative(double m, const std::array<double, 3>& x,
                                                     const std::array<double, 3>& v, const std::array<double, 3>& a) {
  const auto term = [&](int i, int j) { return m * (2 * v[i] * v[j] + x[i] * a[j] + a[i] * x[j]); };
  return {term(0, 0), term(1, 1), term(2, 2), term(0, 1), term(0, 2), term(1, 2)};
}

/// The plus and cross polarisations.
struct polarisations {
  double plus = 0, cross = 0;
};

/// The strain for an observer on the z axis at distance d (the orbital axis of an orbit in the
/// x-y plane): the TT projection onto the x-y plane, h+ = (h_xx - h_yy) / 2 = G (Ï_xx - Ï_yy) / (c^4 d),
/// hx = h_xy = 2 G Ï_xy / (c^4 d). For two point masses on a circular orbit of separation a this
/// has the amplitude 4 G^2 mu M / (c^4 a d) and the frequency 2 Omega.
inline polarisations strain_on_z_axis(const symmetric_tensor& second_derivative, double gravitational_constant,
                                      double speed_of_light, double distance) {
  const double scale = gravitational_constant / (std::pow(speed_of_light, 4) * distance);
  return {scale * (second_derivative[0] - second_derivative[1]), 2 * scale * second_derivative[3]};
}

}  // namespace flecsph::physics
