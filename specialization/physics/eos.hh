// Equations of state: ideal gas P = (gamma-1) rho u, polytrope P = K rho^Gamma, isothermal
// P = c^2 rho; each gives the pressure and the adiabatic sound speed c^2 = (dP/drho)_s.
#pragma once

#include "flecsi_lite/runtime.hh"

#include <Kokkos_Core.hpp>

#include <cmath>
#include <string_view>

namespace flecsph::physics {

/// Ideal gas with adiabatic index gamma; u is the specific internal energy.
struct ideal_gas {
  double gamma = 5.0 / 3.0;

  KOKKOS_INLINE_FUNCTION double pressure(double rho, double u) const { return (gamma - 1.0) * rho * u; }
  /// sqrt(gamma P / rho) = sqrt(gamma (gamma-1) u).
  KOKKOS_INLINE_FUNCTION double sound_speed(double /*rho*/, double u) const {
    return std::sqrt(gamma * (gamma - 1.0) * u);
  }
  /// The u that gives pressure P at density rho (for initial data).
  KOKKOS_INLINE_FUNCTION double internal_energy(double rho, double pressure) const {
    return pressure / ((gamma - 1.0) * rho);
  }
};

/// Barotropic polytrope P = K rho^Gamma (u is ignored).
struct polytropic {
  double polytropic_constant = 1.0;  // K
  double polytropic_exponent = 2.0;  // Gamma

  KOKKOS_INLINE_FUNCTION double pressure(double rho, double /*u*/ = 0.0) const {
    return polytropic_constant * std::pow(rho, polytropic_exponent);
  }
  /// sqrt(dP/drho) = sqrt(Gamma P / rho).
  KOKKOS_INLINE_FUNCTION double sound_speed(double rho, double /*u*/ = 0.0) const {
    return std::sqrt(polytropic_exponent * polytropic_constant * std::pow(rho, polytropic_exponent - 1.0));
  }
  /// u = K rho^(Gamma-1) / (Gamma-1), the internal energy consistent with the first law.
  KOKKOS_INLINE_FUNCTION double internal_energy(double rho) const {
    return polytropic_constant * std::pow(rho, polytropic_exponent - 1.0) / (polytropic_exponent - 1.0);
  }
};

/// Isothermal gas P = c^2 rho with a fixed sound speed c (u is ignored).
struct isothermal {
  double isothermal_sound_speed = 1.0;

  KOKKOS_INLINE_FUNCTION double pressure(double rho, double /*u*/ = 0.0) const {
    return isothermal_sound_speed * isothermal_sound_speed * rho;
  }
  KOKKOS_INLINE_FUNCTION double sound_speed(double /*rho*/ = 0.0, double /*u*/ = 0.0) const {
    return isothermal_sound_speed;
  }
};

enum class eos_type { ideal_gas, polytropic, isothermal };

/// "ideal_gas", "polytropic", "isothermal": the one table of the "eos" key's choices, its help and
/// its errors.
const flecsi_lite::runtime::name_table<eos_type>& eos_names();

/// eos_names().name(type).
std::string_view eos_name(eos_type type);
/// eos_names().value(name): throws std::invalid_argument naming the valid equations of state
/// (and the nearest one) when `name` is unknown.
eos_type eos_from_name(std::string_view name);

/// An equation of state chosen at run time (one branch per particle, outside the pair loops).
struct equation_of_state {
  eos_type type = eos_type::ideal_gas;
  ideal_gas ideal{};
  polytropic polytrope{};
  isothermal constant_temperature{};

  KOKKOS_INLINE_FUNCTION double pressure(double rho, double u) const {
    switch (type) {
      case eos_type::polytropic:
        return polytrope.pressure(rho, u);
      case eos_type::isothermal:
        return constant_temperature.pressure(rho, u);
      case eos_type::ideal_gas:
        break;
    }
    return ideal.pressure(rho, u);
  }
  KOKKOS_INLINE_FUNCTION double sound_speed(double rho, double u) const {
    switch (type) {
      case eos_type::polytropic:
        return polytrope.sound_speed(rho, u);
      case eos_type::isothermal:
        return constant_temperature.sound_speed(rho, u);
      case eos_type::ideal_gas:
        break;
    }
    return ideal.sound_speed(rho, u);
  }
};

}  // namespace flecsph::physics
