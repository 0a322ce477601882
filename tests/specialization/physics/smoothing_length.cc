// Adaptive smoothing length: the h-rho relation, Newton-Raphson convergence on a lattice to
// h = eta (m/rho)^(1/D), and the grad-h factor Omega against finite differences.
#include "specialization/physics/smoothing_length.hh"

#include "specialization/physics/kernels.hh"

#include <catch2/catch.hpp>

#include <cmath>
#include <type_traits>

using namespace flecsph::physics;

namespace {

/// Summation density and its h derivative at a particle of a cubic lattice of spacing `spacing`
/// and particle mass m, by brute force over all lattice points within 2h.
struct density_sums {
  double rho;
  double drho_dh;
};

template<class Kernel>
density_sums lattice_sums(double h, double spacing, double m) {
  constexpr int D = Kernel::dimension;
  const int reach = static_cast<int>(std::ceil(2.0 * h / spacing)) + 1;
  density_sums sums{0.0, 0.0};
  const int ny = D >= 2 ? reach : 0, nz = D >= 3 ? reach : 0;
  for (int i = -reach; i <= reach; ++i)
    for (int j = -ny; j <= ny; ++j)
      for (int k = -nz; k <= nz; ++k) {
        const double r = spacing * std::sqrt(double(i * i + j * j + k * k));
        sums.rho += m * Kernel::value(r, h);
        sums.drho_dh += m * Kernel::h_derivative(r, h);
      }
  return sums;
}

}  // namespace

TEST_CASE("h-rho relation and its inverse", "[smoothing_length]") {
  CHECK(smoothing_length_from_density<1>(0.01, 1.0, 1.2) == Approx(0.012));
  CHECK(smoothing_length_from_density<2>(0.01, 1.0, 1.2) == Approx(0.12));
  CHECK(smoothing_length_from_density<3>(0.001, 1.0, 1.2) == Approx(0.12));
  for (double rho : {0.1, 1.0, 7.0}) {
    CHECK(density_from_smoothing_length<1>(0.3, smoothing_length_from_density<1>(0.3, rho, 1.3), 1.3) == Approx(rho));
    CHECK(density_from_smoothing_length<2>(0.3, smoothing_length_from_density<2>(0.3, rho, 1.3), 1.3) == Approx(rho));
    CHECK(density_from_smoothing_length<3>(0.3, smoothing_length_from_density<3>(0.3, rho, 1.3), 1.3) == Approx(rho));
  }
}

TEMPLATE_TEST_CASE("Newton-Raphson converges on a lattice to h = eta (m/rho)^(1/D)", "[smoothing_length]",
                   cubic_spline<1>, cubic_spline<2>, cubic_spline<3>, wendland_c2<1>, wendland_c2<2>, wendland_c2<3>,
                   wendland_c6<3>) {
  using kernel = TestType;
  constexpr int D = kernel::dimension;
  // Wendland kernels need more neighbours than the cubic spline for a small lattice summation
  // error (Dehnen & Aly 2012, sec. 5); with these eta it is below 0.3% for every kernel here.
  const double eta = std::is_same_v<typename kernel::shape, cubic_spline_shape> ? 1.2 : 1.8;
  const double spacing = 0.1, rho0 = 2.0;
  const double m = rho0 * std::pow(spacing, D);
  const double h_expected = smoothing_length_from_density<D>(m, rho0, eta);  // eta spacing

  for (double start : {0.25, 0.7, 1.4, 1.9}) {  // from far below to far above the answer
    double h = start * h_expected;
    int iterations = 0;
    density_sums sums = lattice_sums<kernel>(h, spacing, m);
    while (std::fabs(smoothing_length_residual<D>(h, sums.rho, m, eta)) > 1e-13 && iterations < 50) {
      h = smoothing_length_newton_step<D>(h, sums.rho, sums.drho_dh, m, eta);
      sums = lattice_sums<kernel>(h, spacing, m);
      ++iterations;
    }
    INFO("start " << start << " h/h_expected " << h / h_expected << " after " << iterations);
    CHECK(iterations < 20);
    // Converged to the fixed point of the h-rho relation with the summation density...
    CHECK(h == Approx(smoothing_length_from_density<D>(m, sums.rho, eta)).epsilon(1e-12));
    // ...which on a lattice is the continuum answer up to the kernel's summation error.
    CHECK(h == Approx(h_expected).epsilon(3e-3));
    // The lattice density barely depends on h there, so Omega is close to 1 (within a few %).
    CHECK(grad_h_omega<D>(h, sums.rho, sums.drho_dh) == Approx(1.0).margin(0.04));
  }
}

TEST_CASE("Newton-Raphson converges quadratically near the root", "[smoothing_length]") {
  using kernel = cubic_spline<2>;
  const double spacing = 0.1, m = spacing * spacing, eta = 1.3;
  double h = 1.15 * eta * spacing;
  double previous = 1.0;
  for (int iteration = 0; iteration < 4; ++iteration) {
    const density_sums sums = lattice_sums<kernel>(h, spacing, m);
    const double residual = std::fabs(smoothing_length_residual<2>(h, sums.rho, m, eta));
    if (residual < 1e-12) break;
    if (iteration >= 2) CHECK(residual < 10.0 * previous * previous);
    previous = residual;
    h = smoothing_length_newton_step<2>(h, sums.rho, sums.drho_dh, m, eta);
  }
}

TEST_CASE("Omega equals (h / (D rho_h)) df/dh by finite differences", "[smoothing_length]") {
  // f(h) = rho_sum(h) - rho_h(h) has f'(h) = (D rho_h / h) Omega where rho_sum = rho_h. Use an
  // irregular neighbourhood so that rho_sum really depends on h (Omega != 1).
  using kernel = wendland_c4<3>;
  const double neighbours[][3] = {{0.0, 0.0, 0.0},  {0.05, 0.01, -0.02},  {-0.03, 0.06, 0.0}, {0.08, -0.07, 0.04},
                                  {0.0, 0.0, 0.11}, {-0.09, -0.02, 0.05}, {0.12, 0.1, -0.06}};
  const double m = 1e-3, eta = 1.2;
  auto sums = [&](double h) {
    density_sums s{0.0, 0.0};
    for (const auto& x : neighbours) {
      const double r = std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
      s.rho += m * kernel::value(r, h);
      s.drho_dh += m * kernel::h_derivative(r, h);
    }
    return s;
  };
  double h = 0.08;
  for (int iteration = 0; iteration < 30; ++iteration) {
    const density_sums s = sums(h);
    h = smoothing_length_newton_step<3>(h, s.rho, s.drho_dh, m, eta);
  }
  const density_sums s = sums(h);
  REQUIRE(std::fabs(smoothing_length_residual<3>(h, s.rho, m, eta)) < 1e-12);
  const double omega = grad_h_omega<3>(h, s.rho, s.drho_dh);
  CHECK(std::fabs(omega - 1.0) > 0.05);
  auto f = [&](double x) { return sums(x).rho - density_from_smoothing_length<3>(m, x, eta); };
  const double step = 1e-6 * h;
  const double df_dh = (f(h + step) - f(h - step)) / (2.0 * step);
  CHECK(df_dh == Approx(3.0 * s.rho / h * omega).epsilon(1e-7));
}
