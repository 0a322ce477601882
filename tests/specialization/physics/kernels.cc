// Properties of every smoothing kernel in D = 1, 2, 3: unit integral, positivity, compact support
// at 2h, continuity, and derivatives (dW/dr, (1/r) dW/dr, dW/dh) equal to finite differences.
#include "specialization/physics/kernels.hh"

#include "specialization/analytic/quadrature.hh"

#include <catch2/catch.hpp>

#include <cmath>

using namespace flecsph::physics;

namespace {

/// Surface of the unit sphere in D dimensions: 2, 2 pi, 4 pi.
double unit_sphere_surface(int dimension) { return dimension == 1 ? 2.0 : (dimension == 2 ? 2.0 * pi : 4.0 * pi); }

constexpr double h = 0.7;  // a smoothing length that is not 1, so powers of h matter

}  // namespace

#define ALL_KERNELS                                                                                                  \
  cubic_spline<1>, cubic_spline<2>, cubic_spline<3>, wendland_c2<1>, wendland_c2<2>, wendland_c2<3>, wendland_c4<1>, \
    wendland_c4<2>, wendland_c4<3>, wendland_c6<1>, wendland_c6<2>, wendland_c6<3>

TEMPLATE_TEST_CASE("kernel integrates to one over R^D", "[kernels]", ALL_KERNELS) {
  using kernel = TestType;
  constexpr int D = kernel::dimension;
  // Radial quadrature int_0^2h W(r) S_D r^(D-1) dr. The panels meet at q = 1, where the cubic
  // spline changes polynomial, so the 20-point rule is exact on each piece.
  const flecsph::analytic::gauss_legendre_rule rule(20);
  const double integral = flecsph::analytic::integrate(
    [](double r) { return kernel::value(r, h) * unit_sphere_surface(D) * std::pow(r, D - 1); }, 0.0, 2.0 * h, 64, rule);
  CHECK(integral == Approx(1.0).epsilon(1e-12));
}

TEMPLATE_TEST_CASE("kernel is non-negative, decreasing and zero from 2h on", "[kernels]", ALL_KERNELS) {
  using kernel = TestType;
  for (int i = 0; i <= 1000; ++i) {
    const double r = 2.5 * h * i / 1000.0;
    INFO("r/h = " << r / h);
    CHECK(kernel::value(r, h) >= 0.0);
    CHECK(kernel::radial_derivative(r, h) <= 0.0);
    CHECK(kernel::in_support(r, h) == (r < 2.0 * h));
    if (r >= 2.0 * h) {
      CHECK(kernel::value(r, h) == 0.0);
      CHECK(kernel::radial_derivative(r, h) == 0.0);
      CHECK(kernel::h_derivative(r, h) == 0.0);
    }
  }
  CHECK(kernel::value(2.0 * h, h) == 0.0);
  CHECK(kernel::value(0.0, h) > 0.0);
  // W and dW/dr reach zero continuously at the support edge.
  const double near_edge = 2.0 * h * (1.0 - 1e-6);
  CHECK(kernel::value(near_edge, h) < 1e-12 * kernel::value(0.0, h));
  CHECK(std::fabs(kernel::radial_derivative(near_edge, h)) < 1e-8 * kernel::value(0.0, h) / h);
}

TEMPLATE_TEST_CASE("kernel and its derivative are continuous at q = 1", "[kernels]", ALL_KERNELS) {
  using kernel = TestType;
  const double below = h * (1.0 - 1e-12), above = h * (1.0 + 1e-12);
  CHECK(kernel::value(below, h) == Approx(kernel::value(above, h)).epsilon(1e-10));
  CHECK(kernel::radial_derivative(below, h) == Approx(kernel::radial_derivative(above, h)).epsilon(1e-10));
  // (dW/dh vanishes at q = 1 for the 3D cubic spline, hence an absolute margin.)
  CHECK(kernel::h_derivative(below, h) ==
        Approx(kernel::h_derivative(above, h)).margin(1e-10 * kernel::value(0.0, h) / h));
}

TEMPLATE_TEST_CASE("kernel derivatives match finite differences", "[kernels]", ALL_KERNELS) {
  using kernel = TestType;
  const double scale = kernel::value(0.0, h) / h;  // typical size of dW/dr and dW/dh
  const double step = 1e-6 * h;
  for (int i = 1; i < 200; ++i) {
    const double r = 2.0 * h * i / 200.0;
    if (std::fabs(r - h) < 2.0 * step) continue;  // the cubic spline's second derivative jumps
    INFO("r/h = " << r / h);
    const double dW_dr = (kernel::value(r + step, h) - kernel::value(r - step, h)) / (2 * step);
    const double dW_dh = (kernel::value(r, h + step) - kernel::value(r, h - step)) / (2 * step);
    CHECK(kernel::radial_derivative(r, h) == Approx(dW_dr).margin(1e-7 * scale));
    CHECK(kernel::h_derivative(r, h) == Approx(dW_dh).margin(1e-7 * scale));
    CHECK(kernel::gradient_factor(r, h) * r == Approx(kernel::radial_derivative(r, h)).epsilon(1e-13));
  }
}

TEMPLATE_TEST_CASE("gradient factor is finite at r = 0 and W is smooth there", "[kernels]", ALL_KERNELS) {
  using kernel = TestType;
  const double at_zero = kernel::gradient_factor(0.0, h);
  CHECK(std::isfinite(at_zero));
  CHECK(at_zero < 0.0);
  CHECK(at_zero == Approx(kernel::gradient_factor(1e-7 * h, h)).epsilon(1e-5));
  CHECK(kernel::radial_derivative(0.0, h) == 0.0);
  // dW/dh at r = 0 is -D W(0)/h (W(0) = sigma / h^D).
  CHECK(kernel::h_derivative(0.0, h) == Approx(-kernel::dimension * kernel::value(0.0, h) / h).epsilon(1e-14));
}

TEST_CASE("cubic spline has the seed's normalization and shape", "[kernels]") {
  // sigma_D of (1.13) and W(q) of the corrected (1.12) at q = 0, 1, 1.5.
  CHECK(cubic_spline<1>::value(0.0, 1.0) == Approx(2.0 / 3.0));
  CHECK(cubic_spline<2>::value(0.0, 1.0) == Approx(10.0 / (7.0 * pi)));
  CHECK(cubic_spline<3>::value(0.0, 1.0) == Approx(1.0 / pi));
  CHECK(cubic_spline<3>::value(1.0, 1.0) == Approx(0.25 / pi));
  CHECK(cubic_spline<3>::value(1.5, 1.0) == Approx(0.25 * 0.125 / pi));
  CHECK(cubic_spline<3>::value(1.0, 2.0) == Approx((1.0 - 1.5 * 0.25 + 0.75 * 0.125) / (8.0 * pi)));
}

TEST_CASE("Wendland kernels have the Dehnen & Aly central values", "[kernels]") {
  // W(0) = N_D / H^D with support H = 2h (Dehnen & Aly 2012, Table 1).
  CHECK(wendland_c2<3>::value(0.0, 0.5) == Approx(21.0 / (2.0 * pi)));
  CHECK(wendland_c4<3>::value(0.0, 0.5) == Approx(495.0 / (32.0 * pi)));
  CHECK(wendland_c6<3>::value(0.0, 0.5) == Approx(1365.0 / (64.0 * pi)));
  CHECK(wendland_c2<2>::value(0.0, 0.5) == Approx(7.0 / pi));
  CHECK(wendland_c6<1>::value(0.0, 0.5) == Approx(55.0 / 32.0));
}
