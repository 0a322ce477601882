// Exact summation: independent of order and grouping, exact where naive sums lose everything.
#include <catch2/catch.hpp>

#include "flecsi_lite/util/exact_sum.hh"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <limits>
#include <random>
#include <vector>

using flecsi_lite::util::exact_sum;

TEST_CASE("exact sums survive catastrophic cancellation") {
  exact_sum s;
  for (double x : {1e16, 1.0, -1e16, 1e-300, -1e-300, 3.0}) s.add(x);
  CHECK(s.value() == 4.0);
  CHECK((1e16 + 1.0 - 1e16 + 3.0) != 4.0);  // what the naive sum gives
}

TEST_CASE("exact sums do not depend on order or grouping") {
  std::mt19937_64 random(7);
  std::uniform_real_distribution<double> mantissa(-1, 1);
  std::uniform_int_distribution<int> exponent(-60, 60);
  std::vector<double> values;
  for (int i = 0; i < 20000; ++i) values.push_back(std::ldexp(mantissa(random), exponent(random)));
  exact_sum forward;
  for (double v : values) forward.add(v);
  std::shuffle(values.begin(), values.end(), random);
  exact_sum a, b, c;  // three "ranks" of different sizes
  for (std::size_t i = 0; i < values.size(); ++i) (i < 5000 ? a : i < 6000 ? b : c).add(values[i]);
  exact_sum grouped = c;
  grouped += a;
  grouped += b;
  CHECK(grouped.value() == forward.value());
  long double reference = 0;  // extended precision, for the magnitude only
  for (double v : values) reference += v;
  CHECK(forward.value() == Approx(static_cast<double>(reference)).epsilon(1e-12));
}

TEST_CASE("exact sums handle the extremes of the double range") {
  const double tiny = std::numeric_limits<double>::denorm_min();
  exact_sum s;
  s.add(tiny);
  s.add(tiny);
  CHECK(s.value() == 2 * tiny);
  exact_sum big;
  big.add(std::numeric_limits<double>::max());
  big.add(-std::numeric_limits<double>::max());
  big.add(-2.5);
  CHECK(big.value() == -2.5);
}

TEST_CASE("one double added comes back exactly, over the whole range of bit patterns") {
  // add() reads the mantissa and the exponent from the bits: every finite double, normal or
  // subnormal, of either sign must survive the round trip, and cancel against its negative.
  std::mt19937_64 random(11);
  int checked = 0;
  for (int i = 0; i < 200000; ++i) {
    std::uint64_t bits = random();
    if (i % 4 == 0) bits &= ~(std::uint64_t(0x7ff) << 52);  // a quarter of them subnormal
    double x = 0;
    std::memcpy(&x, &bits, sizeof x);
    if (!std::isfinite(x)) continue;
    exact_sum one(x);
    exact_sum cancelled(x);
    cancelled.add(-x);
    if (one.value() != x || cancelled.value() != 0) FAIL("x = " << x);
    ++checked;
  }
  CHECK(checked > 190000);
  exact_sum boundary;  // the largest subnormal plus its smallest step is the smallest normal
  boundary.add(std::numeric_limits<double>::min() - std::numeric_limits<double>::denorm_min());
  boundary.add(std::numeric_limits<double>::denorm_min());
  CHECK(boundary.value() == std::numeric_limits<double>::min());
}
