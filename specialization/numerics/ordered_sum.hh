// A sum of pair terms computed lanes<T> at a time (numerics/simd.hh) and added one by one in list
// order, as a plain loop over the list adds them: the bits of the sum are those of the scalar
// loop. The fluid loops use it, so that moving them onto packs changed no output bit; the gas
// loops use simd::striped_sum, faster, whose order differs from a plain loop's.
#pragma once

#include "specialization/numerics/simd.hh"

#include <cstddef>

namespace flecsph::physics::simd {

/// total = ((t0 + t1) + t2) + ... over every term added, starting at +0. A masked term must be +0
/// or -0: a sum that starts at +0 is never -0 in round-to-nearest, and x + (+-0) = x for any other
/// x, so a zero term leaves the sum as skipping it would.
template<class T>
class ordered_sum {
 public:
  /// The next lanes<T> terms, lane 0 first.
  FLECSPH_SIMD_INLINE void add(const T& terms) {
    for (std::size_t i = 0; i < lanes<T>; ++i) total_ += element(terms, i);
  }
  FLECSPH_SIMD_INLINE double total() const { return total_; }

 private:
  double total_ = 0.0;
};

}  // namespace flecsph::physics::simd
