// Pressure-energy SPH (formulation = pressure_energy; Hopkins 2013, MNRAS 428, 2840, sec. 2.4):
// the density task's P_bar and the force task against a direct O(N^2) evaluation of Hopkins'
// equations with adaptive h (his f_ab written out, h from the mass density); momentum and energy
// rates vanishing to round-off; and, for a uniform u, the forces of density-energy SPH (the two
// formulations agree when u does not vary: P_bar = (gamma-1) rho u).
#include "sph_setup.hh"

#include <catch2/catch.hpp>

#include <cmath>
#include <vector>

namespace {
using namespace sph_test;

template<int D>
void prepare(sph::simulation<D>& s, const lattice& shape, bool pressure_energy) {
  s.physics.equations = pressure_energy ? sph::formulation::pressure_energy : sph::formulation::density_energy;
  s.physics.eos.ideal.gamma = 5.0 / 3.0;
  load_lattice(s, shape);
  sph::update_neighbours(s);
  sph::update_density(s);
  sph::update_pressure(s);
  sph::update_forces(s);
  s.next_time_step.get();
}

/// d/dh of W(r, h) = h^-D w(r / h): -(D W + r dW/dr) / h.
template<class Kernel, int D>
double kernel_h_derivative(double r, double h) {
  return -(D * Kernel::value(r, h) + r * Kernel::radial_derivative(r, h)) / h;
}
}  // namespace

TEST_CASE("pressure-energy forces equal a direct evaluation of Hopkins' equations", "[sph][pressure_energy]") {
  constexpr int D = 2;
  using f = sph::fields<D>;
  using Kernel = flecsph::physics::cubic_spline<D>;
  sph::simulation<D> s;
  s.physics.conductivity = 0;  // Hopkins' equations without dissipation
  s.physics.viscosity.alpha = 0;
  s.physics.viscosity.beta = 0;
  prepare(s, {12, true, 1.0, 1.0, 0.3, 0.5, 0.6}, true);
  auto& p = *s.particles;
  const auto x = flecsi_lite::host_view(f::position()(p));
  const auto v = flecsi_lite::host_view(f::velocity(p));
  const auto m = flecsi_lite::host_view(f::mass()(p));
  const auto h = flecsi_lite::host_view(f::smoothing_length()(p));
  const auto u = flecsi_lite::host_view(f::internal_energy(p));
  const auto P = flecsi_lite::host_view(f::pressure(p));
  const auto acceleration = flecsi_lite::host_view(f::acceleration(p));
  const auto du_dt = flecsi_lite::host_view(f::internal_energy_rate(p));
  const std::size_t n = p.owned_size();
  const double gamma = 5.0 / 3.0;
  // At the task's h: rho, Omega = 1 + h / (D rho) drho/dh, P_bar and dP_bar/dh by direct sums.
  std::vector<double> rho(n, 0.0), omega(n), P_bar(n, 0.0), dP_bar_dh(n, 0.0);
  for (std::size_t a = 0; a < n; ++a) {
    double drho_dh = 0;
    for (std::size_t b = 0; b < n; ++b) {
      const double r = norm<D>(image_separation<D>(x(a), x(b), true));
      rho[a] += m(b) * Kernel::value(r, h(a));
      drho_dh += m(b) * kernel_h_derivative<Kernel, D>(r, h(a));
      P_bar[a] += (gamma - 1) * m(b) * u(b) * Kernel::value(r, h(a));
      dP_bar_dh[a] += (gamma - 1) * m(b) * u(b) * kernel_h_derivative<Kernel, D>(r, h(a));
    }
    omega[a] = 1 + h(a) / (D * rho[a]) * drho_dh;
    CHECK(P(a) == Approx(P_bar[a]).epsilon(1e-12));
  }
  // Hopkins' f_ab = 1 - (h_a / (D rho_a Omega_a)) dP_bar_a/dh_a m_b / x_b, x_b = (gamma-1) m_b u_b.
  const auto f_ab = [&](std::size_t a, std::size_t b) {
    return 1 - h(a) / (D * rho[a] * omega[a]) * dP_bar_dh[a] * m(b) / ((gamma - 1) * m(b) * u(b));
  };
  for (std::size_t a = 0; a < n; ++a) {
    sph::vector<D> dv{};
    double du = 0;
    for (std::size_t b = 0; b < n; ++b) {
      const auto r = image_separation<D>(x(a), x(b), true);
      const double distance = norm<D>(r);
      if (distance == 0) continue;
      const double grad_a = Kernel::radial_derivative(distance, h(a)) / distance;  // grad W(h_a) = r grad_a
      const double grad_b = Kernel::radial_derivative(distance, h(b)) / distance;
      const double common = (gamma - 1) * (gamma - 1) * m(b) * u(a) * u(b);
      double r_dot_v = 0;
      for (int k = 0; k < D; ++k) r_dot_v += r[k] * (v(a)[k] - v(b)[k]);
      for (int k = 0; k < D; ++k)
        dv[k] -= common * (f_ab(a, b) / P_bar[a] * grad_a + f_ab(b, a) / P_bar[b] * grad_b) * r[k];
      du += common * f_ab(a, b) / P_bar[a] * grad_a * r_dot_v;
    }
    const double scale = std::fabs(dv[0]) + std::fabs(dv[1]) + 1e-3;
    CHECK(std::fabs(acceleration(a)[0] - dv[0]) < 1e-10 * scale);
    CHECK(std::fabs(acceleration(a)[1] - dv[1]) < 1e-10 * scale);
    CHECK(du_dt(a) == Approx(du).epsilon(1e-9).margin(1e-10 * scale));
  }
}

TEST_CASE("pressure-energy momentum and energy rates vanish to round-off", "[sph][pressure_energy]") {
  const auto check = [](auto dimension, bool periodic) {
    constexpr int D = decltype(dimension)::value;
    using f = sph::fields<D>;
    sph::simulation<D> s;
    prepare(s, {D == 3 ? 7 : 12, periodic, 1.0, 1.0, 0.3, 0.5, 0.6}, true);
    auto& p = *s.particles;
    const auto v = flecsi_lite::host_view(f::velocity(p));
    const auto a = flecsi_lite::host_view(f::acceleration(p));
    const auto m = flecsi_lite::host_view(f::mass()(p));
    const auto du = flecsi_lite::host_view(f::internal_energy_rate(p));
    sph::vector<D> momentum{};
    double energy = 0, force_scale = 0, power_scale = 0;
    for (std::size_t i = 0; i < p.owned_size(); ++i) {
      double power = 0;
      for (int k = 0; k < D; ++k) {
        momentum[k] += m(i) * a(i)[k];
        force_scale += std::fabs(m(i) * a(i)[k]);
        power += v(i)[k] * a(i)[k];
      }
      energy += m(i) * (power + du(i));
      power_scale += std::fabs(m(i) * power) + std::fabs(m(i) * du(i));
    }
    INFO("D = " << D << (periodic ? ", periodic" : ", open"));
    CHECK(force_scale > 0);
    for (int k = 0; k < D; ++k) CHECK(std::fabs(momentum[k]) < 1e-14 * force_scale);
    CHECK(std::fabs(energy) < 1e-13 * power_scale);
  };
  for (bool periodic : {true, false}) {
    check(std::integral_constant<int, 1>{}, periodic);
    check(std::integral_constant<int, 2>{}, periodic);
    check(std::integral_constant<int, 3>{}, periodic);
  }
}

TEST_CASE("with a uniform u pressure-energy gives the forces of density-energy", "[sph][pressure_energy]") {
  constexpr int D = 2;
  using f = sph::fields<D>;
  const lattice jittered{12, false, 1.0, 1.3, 0.3, 0.5, 0.0};  // open box: the edges vary rho
  sph::simulation<D> standard, smoothed;
  prepare(standard, jittered, false);
  prepare(smoothed, jittered, true);
  const auto a1 = flecsi_lite::host_view(f::acceleration(*standard.particles));
  const auto a2 = flecsi_lite::host_view(f::acceleration(*smoothed.particles));
  const auto du1 = flecsi_lite::host_view(f::internal_energy_rate(*standard.particles));
  const auto du2 = flecsi_lite::host_view(f::internal_energy_rate(*smoothed.particles));
  const auto P1 = flecsi_lite::host_view(f::pressure(*standard.particles));
  const auto P2 = flecsi_lite::host_view(f::pressure(*smoothed.particles));
  double scale = 0;
  for (std::size_t i = 0; i < standard.particles->owned_size(); ++i) scale = std::max(scale, std::fabs(a1(i)[0]));
  REQUIRE(scale > 0);
  for (std::size_t i = 0; i < standard.particles->owned_size(); ++i) {
    CHECK(P2(i) == Approx(P1(i)).epsilon(1e-12));
    for (int k = 0; k < D; ++k) CHECK(std::fabs(a2(i)[k] - a1(i)[k]) < 1e-11 * scale);
    CHECK(du2(i) == Approx(du1(i)).epsilon(1e-9).margin(1e-11 * scale));
  }
}
