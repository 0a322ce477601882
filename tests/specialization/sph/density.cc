// The density task against a direct O(N^2) kernel sum over every particle and periodic image
// (fixed h), and the adaptive smoothing length against the h-rho relation and the grad-h factor
// Omega against a finite-difference derivative of the density sum (Price 2012, sec. 3).
#include "sph_setup.hh"

#include <catch2/catch.hpp>

#include <cmath>

namespace {
using namespace sph_test;

/// rho(h) = sum_b m_b W(|x_a - x_b|, h) over every particle, nearest periodic image.
template<int D, class Kernel>
double direct_density(sph::simulation<D>& s, std::size_t a, double h, bool periodic) {
  using f = sph::fields<D>;
  auto& p = *s.particles;
  const auto x = flecsi_lite::host_view(f::position()(p));
  const auto m = flecsi_lite::host_view(f::mass()(p));
  double rho = 0;
  for (std::size_t b = 0; b < p.owned_size(); ++b)
    rho += m(b) * Kernel::value(norm<D>(image_separation<D>(x(a), x(b), periodic)), h);
  return rho;
}

template<int D, class Kernel>
void check_fixed_h(flecsph::physics::kernel_type type, double jitter) {
  using f = sph::fields<D>;
  sph::simulation<D> s;
  s.physics.kernel = type;
  s.physics.adaptive_smoothing_length = false;
  load_lattice(s, {D == 3 ? 6 : 10, true, 1.0, 1.0, jitter});
  sph::update_neighbours(s);
  sph::update_density(s);
  auto& p = *s.particles;
  const auto rho = flecsi_lite::host_view(f::density(p));
  const auto h = flecsi_lite::host_view(f::smoothing_length()(p));
  const auto omega = flecsi_lite::host_view(f::omega(p));
  for (std::size_t a = 0; a < p.owned_size(); ++a) {
    CHECK(rho(a) == Approx(direct_density<D, Kernel>(s, a, h(a), true)).epsilon(1e-13));
    CHECK(omega(a) == 1.0);
  }
  if (jitter == 0) {
    // Every lattice site sees the same neighbourhood; a normalized kernel gives about rho0.
    for (std::size_t a = 0; a < p.owned_size(); ++a) CHECK(rho(a) == Approx(rho(0)).epsilon(1e-12));
    CHECK(rho(0) == Approx(1.0).epsilon(0.03));
  }
}
}  // namespace

TEST_CASE("density at fixed h equals the direct kernel sum over all periodic images", "[sph][density]") {
  using namespace flecsph::physics;
  for (double jitter : {0.0, 0.3}) {
    check_fixed_h<1, cubic_spline<1>>(kernel_type::cubic_spline, jitter);
    check_fixed_h<2, cubic_spline<2>>(kernel_type::cubic_spline, jitter);
    check_fixed_h<3, cubic_spline<3>>(kernel_type::cubic_spline, jitter);
    check_fixed_h<2, wendland_c2<2>>(kernel_type::wendland_c2, jitter);
    check_fixed_h<3, wendland_c4<3>>(kernel_type::wendland_c4, jitter);
  }
}

template<int D>
void check_adaptive() {
  using f = sph::fields<D>;
  using Kernel = flecsph::physics::cubic_spline<D>;
  sph::simulation<D> s;
  s.physics.h_tolerance = 1e-10;
  lattice shape{D == 3 ? 6 : 12, true, 1.0, 1.0, 0.35};
  load_lattice(s, shape);
  sph::update_neighbours(s);
  sph::update_density(s);
  auto& p = *s.particles;
  const auto rho = flecsi_lite::host_view(f::density(p));
  const auto h = flecsi_lite::host_view(f::smoothing_length()(p));
  const auto m = flecsi_lite::host_view(f::mass()(p));
  const auto omega = flecsi_lite::host_view(f::omega(p));
  double spread = 0;
  for (std::size_t a = 0; a < p.owned_size(); ++a) {
    // h solves h = eta (m / rho)^(1/D) with rho the kernel sum at that h.
    const double rho_h = m(a) * std::pow(s.physics.eta / h(a), D);
    CHECK(std::fabs(rho(a) - rho_h) / rho_h < 1e-9);
    CHECK(rho(a) == Approx(direct_density<D, Kernel>(s, a, h(a), true)).epsilon(1e-12));
    // Omega = 1 + h / (D rho) d rho_sum / dh, by a central difference.
    const double step = 1e-5 * h(a);
    const double derivative =
      (direct_density<D, Kernel>(s, a, h(a) + step, true) - direct_density<D, Kernel>(s, a, h(a) - step, true)) /
      (2 * step);
    CHECK(omega(a) == Approx(1.0 + h(a) / (D * rho(a)) * derivative).epsilon(1e-6));
    spread = std::max(spread, std::fabs(h(a) / h(0) - 1));
  }
  CHECK(spread > 1e-3);  // the jitter made the smoothing lengths differ: adaptivity was exercised
}

TEST_CASE("adaptive h satisfies the h-rho relation; Omega is the grad-h factor", "[sph][density]") {
  check_adaptive<1>();
  check_adaptive<2>();
  check_adaptive<3>();
}

TEST_CASE("a smoothing length that outgrows the search reach triggers a new search", "[sph][density]") {
  using f = sph::fields<2>;
  sph::simulation<2> s;
  s.physics.search_margin = 0.0;  // no room: any growth of h must search again
  s.physics.h_tolerance = 1e-10;
  load_lattice(s, {12, true, 1.0, 1.0, 0.0});
  // Start from h much too small: Newton-Raphson grows it beyond the searched reach.
  {
    auto h = flecsi_lite::host_view(f::smoothing_length()(*s.particles));
    for (std::size_t a = 0; a < s.particles->owned_size(); ++a) h(a) *= 0.6;
  }
  sph::update_neighbours(s);
  sph::update_density(s);
  CHECK(s.repeated_searches > 0);
  auto& p = *s.particles;
  const auto rho = flecsi_lite::host_view(f::density(p));
  const auto h = flecsi_lite::host_view(f::smoothing_length()(p));
  for (std::size_t a = 0; a < p.owned_size(); ++a) {
    CHECK(rho(a) == Approx(direct_density<2, flecsph::physics::cubic_spline<2>>(s, a, h(a), true)).epsilon(1e-12));
    CHECK(h(a) == Approx(s.physics.eta / 12).epsilon(0.02));
  }
}
