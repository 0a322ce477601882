// The force task against a direct O(N^2) evaluation of the seed's eqs. (1.8)-(1.11) at fixed h,
// and its conservation properties: total momentum, angular momentum and energy rates vanish to
// round-off (pairwise-antisymmetric forms), and a uniform medium at rest feels no force.
#include "sph_setup.hh"

#include <catch2/catch.hpp>

#include <cmath>

namespace {
using namespace sph_test;

template<int D>
void prepare(sph::simulation<D>& s, const lattice& shape) {
  load_lattice(s, shape);
  sph::update_neighbours(s);
  sph::update_density(s);
  sph::update_pressure(s);
  sph::update_forces(s);
  s.next_time_step.get();
}

/// Rates of the totals: sum m a, sum m x cross a, sum m (v.a + du/dt), and the scales
/// sum |m a|, sum |m v.a| they are compared with.
template<int D>
struct rates {
  sph::vector<D> momentum{};
  std::array<double, 3> torque{};
  double energy = 0, force_scale = 0, power_scale = 0;
};

template<int D>
rates<D> total_rates(sph::simulation<D>& s) {
  using f = sph::fields<D>;
  auto& p = *s.particles;
  const auto x = flecsi_lite::host_view(f::position()(p));
  const auto v = flecsi_lite::host_view(f::velocity(p));
  const auto a = flecsi_lite::host_view(f::acceleration(p));
  const auto m = flecsi_lite::host_view(f::mass()(p));
  const auto du = flecsi_lite::host_view(f::internal_energy_rate(p));
  rates<D> r;
  for (std::size_t i = 0; i < p.owned_size(); ++i) {
    double power = 0;
    for (int k = 0; k < D; ++k) {
      r.momentum[k] += m(i) * a(i)[k];
      r.force_scale += std::fabs(m(i) * a(i)[k]);
      power += v(i)[k] * a(i)[k];
    }
    r.energy += m(i) * (power + du(i));
    r.power_scale += std::fabs(m(i) * power) + std::fabs(m(i) * du(i));
    if constexpr (D >= 2) {
      sph::vector<3> xx{}, aa{};
      for (int k = 0; k < D; ++k) {
        xx[k] = x(i)[k];
        aa[k] = a(i)[k];
      }
      r.torque[0] += m(i) * (xx[1] * aa[2] - xx[2] * aa[1]);
      r.torque[1] += m(i) * (xx[2] * aa[0] - xx[0] * aa[2]);
      r.torque[2] += m(i) * (xx[0] * aa[1] - xx[1] * aa[0]);
    }
  }
  return r;
}

template<int D>
void check_conservation(bool periodic, bool adaptive, bool balsara) {
  sph::simulation<D> s;
  s.physics.adaptive_smoothing_length = adaptive;
  s.physics.balsara = balsara;
  s.physics.eos.ideal.gamma = 1.4;
  prepare(s, {D == 3 ? 7 : 12, periodic, 1.0, 1.0, 0.3, 0.5, 0.4});
  const auto r = total_rates(s);
  for (int k = 0; k < D; ++k) CHECK(std::fabs(r.momentum[k]) < 1e-14 * r.force_scale);
  CHECK(std::fabs(r.energy) < 1e-13 * r.power_scale);
  // Pair forces are central (along r_ab), so the total torque vanishes too (not with periodic images).
  if (!periodic)
    for (double t : r.torque) CHECK(std::fabs(t) < 1e-14 * r.force_scale);
  // The fields of a switch that is off take no memory (fields.hh only_with; the tasks get empty
  // accessors and take Pi_ab's factor 1): the Balsara inputs only with it, alpha only with the
  // Cullen & Dehnen switch (off here).
  using f = sph::fields<D>;
  const auto& storages = s.particles->storages();
  const auto allocated = [&storages](std::size_t id) { return id < storages.size() && storages[id] != nullptr; };
  CHECK(allocated(f::balsara.id()) == balsara);
  CHECK(allocated(f::velocity_curl.id()) == balsara);
  CHECK(allocated(f::velocity_divergence.id()) == balsara);
  CHECK_FALSE(allocated(f::viscosity_alpha.id()));
}
}  // namespace

TEST_CASE("momentum, angular momentum and energy rates vanish to round-off", "[sph][forces]") {
  for (bool adaptive : {false, true}) {
    check_conservation<1>(true, adaptive, false);
    check_conservation<2>(true, adaptive, true);
    check_conservation<3>(true, adaptive, false);
    check_conservation<2>(false, adaptive, false);
    check_conservation<3>(false, adaptive, true);
  }
}

TEST_CASE("a uniform medium at rest feels no force", "[sph][forces]") {
  using f = sph::fields<3>;
  sph::simulation<3> s;
  prepare(s, {6, true, 1.0, 2.0});
  auto& p = *s.particles;
  const auto a = flecsi_lite::host_view(f::acceleration(p));
  const auto du = flecsi_lite::host_view(f::internal_energy_rate(p));
  const auto P = flecsi_lite::host_view(f::pressure(p));
  for (std::size_t i = 0; i < p.owned_size(); ++i) {
    for (int k = 0; k < 3; ++k) CHECK(std::fabs(a(i)[k]) < 1e-11 * P(i) * 6);
    CHECK(du(i) == 0.0);
  }
}

TEST_CASE("forces at fixed h equal a direct evaluation of the seed's eqs. (1.8)-(1.11)", "[sph][forces]") {
  using f = sph::fields<2>;
  using Kernel = flecsph::physics::cubic_spline<2>;
  sph::simulation<2> s;
  s.physics.adaptive_smoothing_length = false;
  s.physics.conductivity = 0;  // the seed has no conductivity
  s.physics.eos.ideal.gamma = 5.0 / 3.0;
  prepare(s, {12, true, 1.0, 1.0, 0.3, 0.5, 0.4});
  auto& p = *s.particles;
  const auto x = flecsi_lite::host_view(f::position()(p));
  const auto v = flecsi_lite::host_view(f::velocity(p));
  const auto m = flecsi_lite::host_view(f::mass()(p));
  const auto h = flecsi_lite::host_view(f::smoothing_length()(p));
  const auto u = flecsi_lite::host_view(f::internal_energy(p));
  const auto acceleration = flecsi_lite::host_view(f::acceleration(p));
  const auto du_dt = flecsi_lite::host_view(f::internal_energy_rate(p));
  const std::size_t n = p.owned_size();
  // Density by (1.3), pressure and sound speed of the ideal gas, all at the common h.
  const double gamma = 5.0 / 3.0, alpha = 1, beta = 2, epsilon = 0.01;
  std::vector<double> rho(n, 0.0), P(n), c(n);
  for (std::size_t a = 0; a < n; ++a) {
    for (std::size_t b = 0; b < n; ++b)
      rho[a] += m(b) * Kernel::value(norm<2>(image_separation<2>(x(a), x(b), true)), h(a));
    P[a] = (gamma - 1) * rho[a] * u(a);
    c[a] = std::sqrt(gamma * P[a] / rho[a]);
  }
  for (std::size_t a = 0; a < n; ++a) {
    sph::vector<2> dv{};
    double du = 0;
    for (std::size_t b = 0; b < n; ++b) {
      const auto r = image_separation<2>(x(a), x(b), true);
      const double distance = norm<2>(r);
      if (distance == 0) continue;
      const sph::vector<2> v_ab{v(a)[0] - v(b)[0], v(a)[1] - v(b)[1]};
      const double r_dot_v = r[0] * v_ab[0] + r[1] * v_ab[1];
      const double h_ab = 0.5 * (h(a) + h(b)), c_ab = 0.5 * (c[a] + c[b]), rho_ab = 0.5 * (rho[a] + rho[b]);
      const double mu = h_ab * r_dot_v / (distance * distance + epsilon * h_ab * h_ab);      // (1.11)
      const double Pi = r_dot_v < 0 ? (-alpha * c_ab * mu + beta * mu * mu) / rho_ab : 0.0;  // (1.10)
      const double dW = Kernel::radial_derivative(distance, h(a)) / distance;                // grad W = r dW
      for (int k = 0; k < 2; ++k)
        dv[k] -= m(b) * (P[a] / (rho[a] * rho[a]) + P[b] / (rho[b] * rho[b]) + Pi) * dW * r[k];  // (1.9)
      du += m(b) * (P[a] / (rho[a] * rho[a]) + 0.5 * Pi) * r_dot_v * dW;                         // (1.8)
    }
    const double scale = std::fabs(dv[0]) + std::fabs(dv[1]) + 1e-3;
    CHECK(std::fabs(acceleration(a)[0] - dv[0]) < 1e-11 * scale);
    CHECK(std::fabs(acceleration(a)[1] - dv[1]) < 1e-11 * scale);
    CHECK(du_dt(a) == Approx(du).epsilon(1e-10).margin(1e-12));
  }
}
