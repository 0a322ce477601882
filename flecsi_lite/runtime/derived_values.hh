// Checks of the quantities a program derives from its parameter keys (lengths, masses, energies,
// counts), made before they are used, so that absurd keys are a parameter_error (exit status 2)
// naming them rather than an overflow later. The message is
// "<program>: <what> = <value> (from <keys>) must be ...".
//
//   const double spacing = checked_length("sedov", "lattice spacing", side / n, "box_side, particles_per_side");
#pragma once

#include <cstdint>
#include <string>

namespace flecsi_lite::runtime {

inline constexpr double most_particles = 1099511627776.0;  ///< 2^40: more is not a sensible run
/// Lengths (coordinates, spacings, h) within [1e-50, 1e50]: powers such as h^(D+1), squared
/// distances and space-filling-curve keys then stay far from overflow and underflow.
inline constexpr double smallest_length = 1e-50, largest_length = 1e50;

/// `value` when it is in [smallest_length, largest_length].
double checked_length(const std::string& program, const std::string& what, double value, const std::string& keys);
/// `value` when it is finite and > 0.
double checked_positive(const std::string& program, const std::string& what, double value, const std::string& keys);
/// llround(value) when value is in [0, most_particles] (NaN is not): counts of particles, layers.
std::int64_t checked_count(const std::string& program, const std::string& what, double value, const std::string& keys);

}  // namespace flecsi_lite::runtime
