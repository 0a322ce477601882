// The Tait equation of state of weakly compressible SPH (Monaghan 1994, JCP 110, 399; Batchelor
// 1967): P = rho0 c0^2 / 7 ((rho / rho0)^7 - 1) + P_background, its sound speed and its inverse.
#pragma once

#include <Kokkos_Core.hpp>

#include <cmath>

namespace flecsph::physics {

/// Tait's stiffened liquid with exponent 7: c0 is chosen about 10 times the flow's largest speed,
/// so that |rho / rho0 - 1| ~ (v / c0)^2 stays near 1%.
struct tait {
  double reference_density = 1000;    ///< rho0
  double reference_sound_speed = 10;  ///< c0
  double background_pressure = 0;     ///< P_b (against tensile instability; 0 at a free surface)
  static constexpr double exponent = 7;

  /// B = rho0 c0^2 / 7
  KOKKOS_INLINE_FUNCTION double stiffness() const {
    return reference_density * reference_sound_speed * reference_sound_speed / exponent;
  }
  KOKKOS_INLINE_FUNCTION double pressure(double rho) const {
    const double ratio = rho / reference_density;
    const double ratio2 = ratio * ratio, ratio3 = ratio2 * ratio;
    return stiffness() * (ratio3 * ratio3 * ratio - 1.0) + background_pressure;
  }
  /// sqrt(dP/drho) = c0 (rho / rho0)^3
  KOKKOS_INLINE_FUNCTION double sound_speed(double rho) const {
    const double ratio = rho / reference_density;
    return reference_sound_speed * ratio * ratio * ratio;
  }
  /// The density at pressure P (walls, hydrostatic initial data).
  KOKKOS_INLINE_FUNCTION double density(double p) const {
    return reference_density * std::pow((p - background_pressure) / stiffness() + 1.0, 1.0 / exponent);
  }
};

}  // namespace flecsph::physics
