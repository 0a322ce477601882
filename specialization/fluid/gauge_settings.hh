// The keys of the fluid's gauges (gauges.hh): where the SPH-interpolated pressure and velocity are
// sampled, how often, into which file, and the height under which the surge front is sought
// (surge_front.hh). Like DualSPHysics' gauges and SPHinXsys' observers, a gauge is a sensor's face:
// a segment sampled at gauge_samples points whose values are averaged (a point is a segment of
// length 0), as the sensors of Lobovsky et al. (2014) and TrixiParticles' interpolate_line.
#pragma once

#include "flecsi_lite/runtime.hh"

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace flecsph::fluid {

/// One gauge: the ends of its face, in units of the problem's reference length.
struct gauge_face {
  std::array<double, 2> first{}, last{};
};

struct gauge_settings {
  /// x1, y1, x2, y2 per gauge (units of the reference length; key `gauges`).
  std::vector<double> coordinates;
  std::int64_t samples = 10;  ///< points along a face (a point gauge: 1)
  std::string file;           ///< "" (none): no gauge file; "auto": <output stem>.gauges.csv
  std::int64_t every = 1;     ///< steps between rows (the first step always has one)
  /// Fluid particles at most this far above the floor are candidates for the surge front (units
  /// of the reference length).
  double front_height = 0.2;
  /// The interpolation's smoothing length over the particles' own h: 1 reads the SPH field; more
  /// smooths the reading in space (TrixiParticles' sensors use 2 times their h = 2 dx, i.e. 4 dx).
  double smoothing = 1.0;

  /// The faces of `coordinates` (a parameter_error names the key unless it holds groups of 4).
  std::vector<gauge_face> faces() const;
};

/// The keys gauges, gauge_samples, gauge_file, gauge_every, front_height, gauge_smoothing.
const flecsi_lite::runtime::parameter_block<gauge_settings>& gauge_parameters();

}  // namespace flecsph::fluid
