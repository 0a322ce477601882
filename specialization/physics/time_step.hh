// The Courant condition of one particle's time step (Monaghan 1992, ARA&A 30, 543; GADGET-2:
// Springel 2005, MNRAS 364, 1105, eq. 16, with its signal velocity): a sound wave, or an
// approaching neighbour, crosses at most a fraction C of the particle's smoothing length.
#pragma once

#include <Kokkos_Core.hpp>

namespace flecsph::physics {

/// Courant time step of one particle, C h / max_b v_sig,ab (viscosity.hh: signal_velocity).
KOKKOS_INLINE_FUNCTION double courant_time_step(double courant, double h, double max_signal_velocity) {
  return courant * h / max_signal_velocity;
}

}  // namespace flecsph::physics
