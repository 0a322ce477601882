// Gauss-Legendre quadrature: exact for polynomials of degree 2n - 1, weights sum to 2.
#include "specialization/analytic/quadrature.hh"

#include <catch2/catch.hpp>

#include <cmath>
#include <stdexcept>

using namespace flecsph::analytic;

TEST_CASE("Gauss-Legendre rules integrate polynomials of degree 2n-1 exactly", "[quadrature]") {
  for (int n = 1; n <= 24; ++n) {
    const gauss_legendre_rule rule(n);
    double weight_sum = 0.0;
    for (double w : rule.weights) weight_sum += w;
    CHECK(weight_sum == Approx(2.0).epsilon(1e-14));
    for (int degree = 0; degree <= 2 * n - 1; ++degree) {
      INFO("n = " << n << ", degree = " << degree);
      // int_0^3 x^k dx = 3^(k+1) / (k+1) with a single panel
      const double exact = std::pow(3.0, degree + 1) / (degree + 1);
      const double value = integrate([&](double x) { return std::pow(x, degree); }, 0.0, 3.0, 1, rule);
      CHECK(value == Approx(exact).epsilon(1e-13));
    }
    // ...and not degree 2n (the test can tell: its error is still visible for small n).
    if (n <= 5) {
      const double exact = std::pow(3.0, 2 * n + 1) / (2 * n + 1);
      CHECK(integrate([&](double x) { return std::pow(x, 2 * n); }, 0.0, 3.0, 1, rule) != Approx(exact).epsilon(1e-9));
    }
  }
  CHECK_THROWS_AS(gauss_legendre_rule(0), std::invalid_argument);
}

TEST_CASE("composite rule converges for a smooth non-polynomial integrand", "[quadrature]") {
  const gauss_legendre_rule rule(5);
  const double value = integrate([](double x) { return std::exp(-x) * std::sin(3.0 * x); }, 0.0, 2.0, 16, rule);
  const double exact = (3.0 - std::exp(-2.0) * (std::sin(6.0) + 3.0 * std::cos(6.0))) / 10.0;
  CHECK(value == Approx(exact).epsilon(1e-13));
}
