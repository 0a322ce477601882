// The Tait equation of state: P(rho0) = P_b, c^2 = dP/drho by finite differences, the inverse
// density(P), and the hydrostatic compression g H / c0^2 of a column of depth H.
#include "specialization/physics/tait.hh"

#include <catch2/catch.hpp>

#include <cmath>

using flecsph::physics::tait;

TEST_CASE("Tait EOS: reference state, sound speed and inverse", "[eos][tait]") {
  const tait eos{1000, 20, 50};
  CHECK(eos.pressure(1000) == Approx(50));
  CHECK(eos.stiffness() == Approx(1000 * 400 / 7.0));
  CHECK(eos.pressure(1010) == Approx(eos.stiffness() * (std::pow(1.01, 7) - 1) + 50));
  for (double rho : {990.0, 1000.0, 1013.0}) {
    const double step = 1e-4;
    const double c2 = (eos.pressure(rho + step) - eos.pressure(rho - step)) / (2 * step);
    CHECK(eos.sound_speed(rho) * eos.sound_speed(rho) == Approx(c2).epsilon(1e-8));
    CHECK(eos.density(eos.pressure(rho)) == Approx(rho).epsilon(1e-14));
  }
}

TEST_CASE("Tait EOS: a column of depth H is compressed by about g H / c0^2 at its bottom", "[eos][tait]") {
  const tait eos{1000, 31.3, 0};
  const double g = 9.81, H = 1;
  const double bottom = eos.density(1000 * g * H);
  // (1 + 7 g H / c0^2)^(1/7) - 1 = g H / c0^2 (1 - 3 g H / c0^2 + ...)
  CHECK(bottom / 1000 - 1 == Approx(std::pow(1 + 7 * g * H / (31.3 * 31.3), 1 / 7.0) - 1).epsilon(1e-12));
  CHECK(bottom / 1000 - 1 == Approx(g * H / (31.3 * 31.3)).epsilon(0.04));
}
