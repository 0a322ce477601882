// The integer timeline of individual time steps (GADGET-2: Springel 2005, MNRAS 364, 1105,
// sec. 5; SWIFT's time integration): the run's span [origin, end_time] in 2^bins ticks, each
// particle's step 2^bin ticks starting on a multiple of 2^bin. Integer times make "which
// particles end their step now" exact, so the active set, hence every result, is the same on any
// rank count.
#pragma once

#include <cmath>
#include <cstdint>

namespace flecsph::sph {

struct timeline {
  /// Bins 0..bins: bin `bins` is the whole span; 2^-40 of it is far below any useful step.
  static constexpr int bins = 40;
  static constexpr std::int64_t span = std::int64_t{1} << bins;

  double origin = 0;      ///< the time of tick 0
  double tick = 0;        ///< (end_time - origin) / span
  std::int64_t now = 0;   ///< the current time, in ticks
  std::int64_t next = 0;  ///< the end of the step about to be taken (the earliest particle's end)

  /// Starts at `start` with `end` at the last tick.
  static timeline spanning(double start, double end) {
    timeline t;
    t.origin = start;
    t.tick = std::ldexp(end - start, -bins);
    return t;
  }
  static std::int64_t ticks_of(int bin) { return std::int64_t{1} << bin; }
  /// The time of tick `at` (end_time itself at the last tick).
  double time_at(std::int64_t at, double end_time) const {
    return at >= span ? end_time : origin + static_cast<double>(at) * tick;
  }
  double duration(std::int64_t ticks) const { return static_cast<double>(ticks) * tick; }
  double end_time() const { return origin + std::ldexp(tick, bins); }
};

/// The largest bin whose step fits in dt (at most `largest`); -1 when even one tick is longer.
inline int bin_of_step(double dt, double tick, int largest) {
  if (!(dt >= tick)) return -1;     // NaN too
  int bin = std::ilogb(dt / tick);  // floor(log2) of a value >= 1
  if (bin > largest) bin = largest;
  while (bin > 0 && std::ldexp(tick, bin) > dt) --bin;  // ilogb of the rounded quotient
  return bin;
}

/// The largest bin <= wanted whose steps can start at tick `at` (at a multiple of 2^bin).
inline int aligned_bin(int wanted, std::int64_t at) {
  int bin = wanted;
  while (bin > 0 && at % timeline::ticks_of(bin) != 0) --bin;
  return bin;
}

}  // namespace flecsph::sph
