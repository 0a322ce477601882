// The kernel-softened gravity (physics/gravity_softening.hh, Price & Monaghan 2007) for every 3D
// kernel: pieces equal to the shape, mass fraction = the kernel's integral, g = d phi / dr and
// d phi / dh equal to finite differences, continuity at the pieces' edges and the support,
// Newtonian beyond it, finite at r = 0, and the cubic spline against its published closed form.
#include "specialization/physics/gravity_softening.hh"

#include "specialization/analytic/quadrature.hh"

#include <catch2/catch.hpp>

#include <cmath>

using namespace flecsph::physics;

namespace {
constexpr double h = 0.7;  // not 1, so that the powers of h matter

template<class Shape>
double piece_value(double q) {
  using pieces = kernel_pieces<Shape>;
  const auto c = pieces::coefficients();
  std::size_t k = 0;
  while (k + 1 < pieces::pieces && q >= pieces::edges[k + 1]) ++k;
  double sum = 0, power = 1;
  for (std::size_t n = 0; n < pieces::terms; ++n, power *= q) sum += c[k][n] * power;
  return sum;
}

/// 4 pi sigma int_0^q f(t) t^2 dt by Gauss-Legendre on panels split at the pieces' edges (exact
/// for polynomials up to degree 39 on each panel).
template<class Shape>
double integrated_mass(double q) {
  const flecsph::analytic::gauss_legendre_rule rule(20);
  const auto& edges = kernel_pieces<Shape>::edges;
  double sum = 0;
  for (std::size_t k = 0; k + 1 < edges.size() && edges[k] < q; ++k)
    sum += flecsph::analytic::integrate([](double t) { return Shape::template value<3>(t) * t * t; }, edges[k],
                                        std::min(q, edges[k + 1]), 1, rule);
  return 4.0 * pi * Shape::template normalization<3>() * sum;
}
}  // namespace

#define ALL_SHAPES cubic_spline_shape, wendland_c2_shape, wendland_c4_shape, wendland_c6_shape

TEMPLATE_TEST_CASE("the softening's polynomial pieces are the kernel's shape", "[gravity][softening]", ALL_SHAPES) {
  for (int i = 0; i < 2000; ++i) {
    const double q = 2.0 * i / 2000.0;
    INFO("q = " << q);
    // The monomial form loses digits to cancellation near q = 2 (C6: terms up to 1e4 there).
    CHECK(piece_value<TestType>(q) == Approx(TestType::template value<3>(q)).margin(1e-12));
  }
}

TEMPLATE_TEST_CASE("g r^2 is the kernel's mass within r, 1 beyond the support", "[gravity][softening]", ALL_SHAPES) {
  using soft = softened_gravity<TestType>;
  CHECK(soft::mass_fraction(2.0) == 1.0);
  CHECK(soft::mass_fraction(2.0 * (1 - 1e-15)) == Approx(1.0).margin(1e-14));
  for (int i = 1; i <= 400; ++i) {
    const double q = 2.5 * i / 400.0, r = q * h;
    INFO("q = " << q);
    const double expected = q < 2 ? integrated_mass<TestType>(q) : 1.0;
    CHECK(soft::mass_fraction(q) == Approx(expected).margin(1e-14));
    CHECK(soft::force(r, h) * r * r == Approx(expected).margin(1e-13));
    if (q >= 2) {
      CHECK(soft::force(r, h) == Approx(1.0 / (r * r)).epsilon(1e-15));
      CHECK(soft::radial(r, h) == 1.0 / (r * r * r));
      CHECK(soft::potential(r, h) == -1.0 / r);
      CHECK(soft::h_derivative(r, h) == 0.0);
    }
  }
}

TEMPLATE_TEST_CASE("phi is -1/(2h) minus the integral of g from r to 2h", "[gravity][softening]", ALL_SHAPES) {
  using soft = softened_gravity<TestType>;
  const flecsph::analytic::gauss_legendre_rule rule(20);
  for (int i = 0; i <= 40; ++i) {
    const double r = 2.0 * h * i / 40.0;
    const double integral =
      flecsph::analytic::integrate([](double s) { return soft::force(s, h); }, r, 2.0 * h, 64, rule);
    INFO("r/h = " << r / h);
    CHECK(soft::potential(r, h) == Approx(-1.0 / (2.0 * h) - integral).margin(1e-12));
  }
}

TEMPLATE_TEST_CASE("phi, g and d phi / dh are continuous at the pieces' edges and at the support",
                   "[gravity][softening]", ALL_SHAPES) {
  using soft = softened_gravity<TestType>;
  for (const double edge : kernel_pieces<TestType>::edges) {
    if (edge == 0) continue;
    const double below = edge * h * (1 - 1e-12), above = edge * h * (1 + 1e-12);
    INFO("edge q = " << edge);
    CHECK(soft::potential(below, h) == Approx(soft::potential(above, h)).margin(1e-10));
    CHECK(soft::force(below, h) == Approx(soft::force(above, h)).margin(1e-10));
    CHECK(soft::h_derivative(below, h) == Approx(soft::h_derivative(above, h)).margin(1e-10));
  }
  // At the support: the Newtonian values, reached from inside.
  const double inside = 2.0 * h * (1 - 1e-13);
  CHECK(soft::potential(inside, h) == Approx(-1.0 / (2.0 * h)).margin(1e-12));
  CHECK(soft::force(inside, h) == Approx(1.0 / (4.0 * h * h)).margin(1e-12));
  CHECK(soft::h_derivative(inside, h) == Approx(0.0).margin(1e-12));
}

TEMPLATE_TEST_CASE("g = d phi / dr and d phi / dh equal finite differences", "[gravity][softening]", ALL_SHAPES) {
  using soft = softened_gravity<TestType>;
  // A step large enough that the rounding of phi (1e-14) stays below the bounds.
  const double step = 1e-4;
  for (int i = 1; i < 250; ++i) {
    const double r = 2.5 * h * i / 250.0;
    INFO("r/h = " << r / h);
    const double dphi_dr = (soft::potential(r + step, h) - soft::potential(r - step, h)) / (2 * step);
    const double dphi_dh = (soft::potential(r, h + step) - soft::potential(r, h - step)) / (2 * step);
    CHECK(soft::force(r, h) == Approx(dphi_dr).epsilon(1e-6).margin(1e-7));
    CHECK(soft::h_derivative(r, h) == Approx(dphi_dh).epsilon(1e-6).margin(1e-7));
    CHECK(soft::radial(r, h) * r == Approx(soft::force(r, h)).epsilon(1e-15));
  }
}

TEMPLATE_TEST_CASE("the softened gravity is finite at r = 0: the self potential and no self force",
                   "[gravity][softening]", ALL_SHAPES) {
  using soft = softened_gravity<TestType>;
  const double phi0 = soft::potential(0.0, h), radial0 = soft::radial(0.0, h);
  CHECK(std::isfinite(phi0));
  CHECK(phi0 < 0);
  CHECK(phi0 == Approx(soft::potential(1e-9 * h, h)).epsilon(1e-12));
  CHECK(std::isfinite(radial0));
  CHECK(radial0 == Approx(soft::radial(1e-6 * h, h)).epsilon(1e-9));
  CHECK(soft::force(0.0, h) == 0.0);
  // The self term depends on h: d phi(0, h) / dh = -phi(0, h) / h > 0.
  CHECK(soft::h_derivative(0.0, h) == Approx(-phi0 / h).epsilon(1e-14));
  // Softening only weakens gravity: |phi| <= 1/r and g <= 1/r^2 everywhere.
  for (int i = 1; i <= 200; ++i) {
    const double r = 2.0 * h * i / 200.0;
    CHECK(-soft::potential(r, h) <= 1.0 / r * (1 + 1e-12));
    CHECK(soft::force(r, h) <= 1.0 / (r * r) * (1 + 1e-12));
  }
}

TEST_CASE("the cubic spline softening is Price & Monaghan's closed form", "[gravity][softening]") {
  using soft = softened_gravity<cubic_spline_shape>;
  // Price & Monaghan (2007), eqs. A1-A2 (Monaghan's M4 softening, e.g. Hernquist & Katz 1989).
  const auto published = [](double q) {
    if (q < 1) return 2.0 / 3.0 * q * q - 0.3 * std::pow(q, 4) + 0.1 * std::pow(q, 5) - 1.4;
    if (q < 2)
      return 4.0 / 3.0 * q * q - q * q * q + 0.3 * std::pow(q, 4) - std::pow(q, 5) / 30.0 - 1.6 + 1.0 / (15.0 * q);
    return -1.0 / q;
  };
  for (int i = 0; i <= 300; ++i) {
    const double q = 2.5 * i / 300.0;
    if (q == 0) continue;
    INFO("q = " << q);
    CHECK(soft::potential(q * h, h) == Approx(published(q) / h).margin(1e-14));
  }
  CHECK(soft::potential(0.0, h) == Approx(-1.4 / h).epsilon(1e-15));
}
