// The quadrupole strain (physics/gravitational_waves.hh): Ï_ij from x, v, a equals the second time
// derivative of I_ij (finite differences of an analytic trajectory, here only), and two point masses
// on a circular orbit radiate h+, hx of amplitude 4 G^2 mu M / (c^4 a d) at the frequency 2 Omega.
#include "specialization/physics/gravitational_waves.hh"

#include <catch2/catch.hpp>

#include <array>
#include <cmath>
#include <vector>

using namespace flecsph::physics;
using vec = std::array<double, 3>;

namespace {
/// Ï_ij of two point masses on a circular orbit in the x-y plane about their centre of mass (the
/// origin) at time t, and the orbit's Omega.
struct binary {
  double m1, m2, a, G;
  double omega() const { return std::sqrt(G * (m1 + m2) / (a * a * a)); }
  symmetric_tensor rate(double t) const {
    symmetric_tensor sum{};
    const double w = omega(), phase = w * t;
    const double r[2] = {a * m2 / (m1 + m2), -a * m1 / (m1 + m2)};  // signed distances from the centre of mass
    const double m[2] = {m1, m2};
    for (int b = 0; b < 2; ++b) {
      const vec x{r[b] * std::cos(phase), r[b] * std::sin(phase), 0};
      const vec v{-w * x[1], w * x[0], 0};
      const vec acc{-w * w * x[0], -w * w * x[1], 0};
      const auto term = quadrupole_second_derivative(m[b], x, v, acc);
      for (int k = 0; k < 6; ++k) sum[k] += term[k];
    }
    return sum;
  }
};
}  // namespace

TEST_CASE("Ï_ij from positions, velocities and accelerations is the second derivative of I_ij", "[gw]") {
  // A particle on an arbitrary smooth (non-circular) trajectory.
  const auto x = [](double t) { return vec{std::cos(1.3 * t) + 0.2 * t, 0.5 * std::sin(0.7 * t), t * t - 0.3}; };
  const auto v = [](double t) { return vec{-1.3 * std::sin(1.3 * t) + 0.2, 0.35 * std::cos(0.7 * t), 2 * t}; };
  const auto a = [](double t) { return vec{-1.69 * std::cos(1.3 * t), -0.245 * std::sin(0.7 * t), 2.0}; };
  const double m = 2.5;
  const auto inertia = [&](double t) {
    const vec p = x(t);
    return symmetric_tensor{m * p[0] * p[0], m * p[1] * p[1], m * p[2] * p[2],
                            m * p[0] * p[1], m * p[0] * p[2], m * p[1] * p[2]};
  };
  for (const double t : {0.0, 0.4, 1.7}) {
    const double step = 1e-4;
    const auto plus = inertia(t + step), here = inertia(t), minus = inertia(t - step);
    const auto exact = quadrupole_second_derivative(m, x(t), v(t), a(t));
    for (int k = 0; k < 6; ++k)
      CHECK(exact[k] == Approx((plus[k] - 2 * here[k] + minus[k]) / (step * step)).epsilon(1e-5).margin(1e-6));
  }
}

TEST_CASE("a circular binary: amplitude 4 G^2 mu M / (c^4 a d) at twice the orbital frequency", "[gw]") {
  const binary orbit{1.4, 0.9, 30.0, 1.7};  // unequal masses, G != 1
  const double c = 3.0, d = 1e4;
  const double M = orbit.m1 + orbit.m2, mu = orbit.m1 * orbit.m2 / M;
  const double expected = 4 * orbit.G * orbit.G * mu * M / (std::pow(c, 4) * orbit.a * d);
  const double period = 2 * std::acos(-1.0) / orbit.omega();
  // Sampled over three orbits: the largest |h+| and |hx|, |h| = sqrt(h+^2 + hx^2) (constant for a
  // circular orbit), and the frequency from the unwrapped phase of h+ + i hx.
  const int samples = 3000;
  double largest_plus = 0, largest_cross = 0, previous = 0, unwrapped = 0, first = 0;
  for (int n = 0; n <= samples; ++n) {
    const double t = 3 * period * n / samples;
    const auto h = strain_on_z_axis(orbit.rate(t), orbit.G, c, d);
    largest_plus = std::max(largest_plus, std::fabs(h.plus));
    largest_cross = std::max(largest_cross, std::fabs(h.cross));
    CHECK(std::hypot(h.plus, h.cross) == Approx(expected).epsilon(1e-10));
    const double phase = std::atan2(h.cross, h.plus);
    if (n == 0)
      first = unwrapped = phase;
    else
      unwrapped += std::remainder(phase - previous, 2 * std::acos(-1.0));
    previous = phase;
  }
  CHECK(largest_plus == Approx(expected).epsilon(0.01));
  CHECK(largest_cross == Approx(expected).epsilon(0.01));
  const double frequency = (unwrapped - first) / (3 * period);  // angular
  CHECK(frequency == Approx(2 * orbit.omega()).epsilon(0.01));
  // The strain falls as 1/d and scales as G / c^4 at fixed Ï.
  const auto near = strain_on_z_axis(orbit.rate(0.3), orbit.G, c, d);
  const auto far = strain_on_z_axis(orbit.rate(0.3), orbit.G, c, 2 * d);
  CHECK(far.plus == Approx(near.plus / 2));
}
