// The series solutions of the channel flows: zero at t = 0 (from rest), the steady profiles at
// large t (parabola of maximum F L^2 / (8 nu), linear Couette profile), no slip at the walls, and
// the decay of the slowest mode at intermediate times.
#include "specialization/analytic/channel_flow.hh"

#include <catch2/catch.hpp>

#include <cmath>

using namespace flecsph::analytic;

TEST_CASE("Poiseuille series: from rest to the parabola", "[analytic][channel]") {
  const double L = 1e-3, F = 2e-4, nu = 1e-6, vmax = F * L * L / (8 * nu);
  for (double y : {0.1 * L, 0.5 * L, 0.83 * L}) {
    CHECK(std::fabs(poiseuille_velocity(y, 0, L, F, nu)) < 1e-4 * vmax);
    CHECK(poiseuille_velocity(y, 10 * L * L / nu, L, F, nu) == Approx(F / (2 * nu) * y * (L - y)).epsilon(1e-12));
  }
  CHECK(poiseuille_velocity(0.5 * L, 100, L, F, nu) == Approx(vmax));
  CHECK(poiseuille_velocity(0, 0.1, L, F, nu) == Approx(0).margin(1e-20));
  // At t = 0.2 L^2/nu the first mode dominates the deficit: 32/pi^3 exp(-pi^2 0.2) v_max at the centre.
  const double deficit = vmax - poiseuille_velocity(0.5 * L, 0.2 * L * L / nu, L, F, nu);
  CHECK(deficit ==
        Approx(32 / std::pow(3.14159265358979, 3) * std::exp(-3.14159265358979 * 3.14159265358979 * 0.2) * vmax)
          .epsilon(1e-3));
}

TEST_CASE("Couette series: from rest to the linear profile", "[analytic][channel]") {
  const double L = 1e-3, v0 = 2.5e-5, nu = 1e-6;
  for (double y : {0.2 * L, 0.5 * L, 0.9 * L}) {
    CHECK(std::fabs(couette_velocity(y, 1e-4 * L * L / nu, L, v0, nu)) < 0.05 * v0);
    CHECK(couette_velocity(y, 10 * L * L / nu, L, v0, nu) == Approx(v0 * y / L).epsilon(1e-12));
  }
  CHECK(couette_velocity(L, 0.1, L, v0, nu) == Approx(v0).epsilon(1e-9));
}
