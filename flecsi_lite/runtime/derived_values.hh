// Checks of the quantities a program derives from its parameter keys (lengths, masses, energies,
// counts), made before they are used, so that absurd keys are a parameter_error (exit status 2)
// naming them rather than an overflow later. The message is
// "<program>: <what> = <value> (from <keys>) must be ...".
//
//   const double spacing = checked_length("sedov", "lattice spacing", side / n, "box_side, particles_per_side");
#pragma once

#include "flecsi_lite/runtime/runtime.hh"

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

/// The fewest bytes a particle needs in any app's run: the growth of the peak resident memory
/// with the particle count is 305 bytes in sod 1D with global steps, the smallest run (465 in the
/// 2D dam break; docs/fuzzing.md gives the commands), less a margin for other builds. Fewer than
/// any real run needs, so a refusal is never wrong.
inline constexpr double least_bytes_per_particle = 250;
/// The particle count checked_count(program, "particles", value, keys) when value particles fit
/// in `memory` bytes at least_bytes_per_particle each (by default the job's memory, which the
/// runtime finds at start-up); else a parameter_error naming the keys, the bytes the count needs
/// and the bytes there are, before anything is allocated.
std::int64_t checked_particles(const std::string& program, double value, const std::string& keys,
                               double memory = current_settings().job_memory);

}  // namespace flecsi_lite::runtime
