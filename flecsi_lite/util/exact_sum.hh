// Exact summation of doubles with a fixed-point "superaccumulator" (Kulisch's long accumulator;
// see Demmel & Nguyen, "Parallel reproducible summation", IEEE TC 2015). The sum does not depend
// on the order of additions, so it is the same on any number of ranks and threads.
#pragma once

#include <cmath>
#include <cstdint>
#include <cstring>

namespace flecsi_lite::util {

class exact_sum {
 public:
  // Bit k of the accumulator has weight 2^(k - 1074): the smallest subnormal is bit 0.
  static constexpr int digit_bits = 32;
  static constexpr int digits = 68;  // 2176 bits: every finite double, with room for carries
  static constexpr std::uint64_t mask = 0xffffffffu;

  exact_sum() = default;
  explicit exact_sum(double x) { add(x); }

  void add(double x) {
    if (x == 0) return;
    // The mantissa and exponent read from the IEEE 754 bits (frexp and ldexp cost several times
    // the rest of add): x = mantissa * 2^(position - 1074), exactly, subnormals included.
    std::uint64_t bits = 0;
    std::memcpy(&bits, &x, sizeof bits);
    const int biased_exponent = static_cast<int>((bits >> 52) & 0x7ff);
    std::uint64_t mantissa = bits & ((std::uint64_t(1) << 52) - 1);
    int position = 0;            // bit position of the mantissa's lowest bit
    if (biased_exponent != 0) {  // normal: the implicit leading bit
      mantissa |= std::uint64_t(1) << 52;
      position = biased_exponent - 1;
    }
    // mantissa * 2^shift spans three 32-bit digits; split it without 128-bit integers.
    const int digit = position / digit_bits, shift = position % digit_bits;
    const std::uint64_t low = (mantissa & mask) << shift;
    const std::uint64_t high = (mantissa >> digit_bits) << shift;
    const std::int64_t parts[3] = {std::int64_t(low & mask), std::int64_t((low >> digit_bits) + (high & mask)),
                                   std::int64_t(high >> digit_bits)};
    const std::int64_t sign = (bits >> 63) ? -1 : 1;
    for (int k = 0; k < 3 && digit + k < digits; ++k) digits_[digit + k] += sign * parts[k];
    if (++pending_ == (1 << 30)) normalize();
  }

  exact_sum& operator+=(const exact_sum& other) {
    normalize();
    exact_sum o = other;
    o.normalize();
    for (int k = 0; k < digits; ++k) digits_[k] += o.digits_[k];
    normalize();
    return *this;
  }
  exact_sum& operator+=(double x) {
    add(x);
    return *this;
  }

  /// The sum rounded to double (a function of the exact sum only, hence reproducible).
  double value() const {
    exact_sum copy = *this;
    copy.normalize();
    const bool negative = copy.digits_[digits - 1] < 0;
    if (negative)
      for (auto& d : copy.digits_) d = -d;
    copy.normalize();
    double result = 0;
    for (int k = 0; k < digits; ++k)
      if (copy.digits_[k]) result += std::ldexp(static_cast<double>(copy.digits_[k]), k * digit_bits - 1074);
    return negative ? -result : result;
  }

 private:
  /// Carries so that every digit but the last lies in [0, 2^32): a unique representation.
  void normalize() {
    for (int k = 0; k + 1 < digits; ++k) {
      const std::int64_t carry = digits_[k] >> digit_bits;  // floor division, also for negatives
      digits_[k] -= carry * (std::int64_t(1) << digit_bits);
      digits_[k + 1] += carry;
    }
    pending_ = 0;
  }

  std::int64_t digits_[digits] = {};
  std::int64_t pending_ = 0;
};

}  // namespace flecsi_lite::util
