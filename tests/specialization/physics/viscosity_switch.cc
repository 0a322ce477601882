// The Cullen & Dehnen (2010) switch's per-particle functions (physics/viscosity_switch.hh): the
// limiter's limits (pure compression, pure shear, smooth converging flow), alpha_loc's limits
// and its value by hand, the instant rise, the exponential decay over tau = H / (2 l v_sig), and
// the bounds alpha_min, alpha_max, and the starting alpha.
#include "specialization/physics/viscosity_switch.hh"

#include <catch2/catch.hpp>

#include <cmath>

using namespace flecsph::physics;

TEST_CASE("the limiter is 1 in pure compression and 0 in pure shear", "[viscosity_switch]") {
  CHECK(cullen_dehnen_limiter(-3.0, 0.0, -1.0) == 1.0);
  CHECK(cullen_dehnen_limiter(0.0, 2.0, -1.0) == 0.0);
  CHECK(cullen_dehnen_limiter(0.0, 0.0, 0.0) == 1.0);  // at rest: nothing to limit
  // A shock (every neighbour converging, R = -1) counts its compression (2 * 16 div v)^2 against
  // the shear: with |div v| = 1 and tr(S S^T) = 1, xi = 1024 / 1025.
  CHECK(cullen_dehnen_limiter(-1.0, 1.0, -1.0) == Approx(1024.0 / 1025.0));
  // The same gradients where every neighbour expands (R = 1): the compression term vanishes.
  CHECK(cullen_dehnen_limiter(-1.0, 1.0, 1.0) == 0.0);
  // R = 0: (2 div v)^2 / ((2 div v)^2 + S2) = 4 / 5.
  CHECK(cullen_dehnen_limiter(-1.0, 1.0, 0.0) == Approx(0.8));
}

TEST_CASE("alpha_loc: zero without growing compression, alpha_max H^2 A / (v^2 + H^2 A)", "[viscosity_switch]") {
  CHECK(cullen_dehnen_local_alpha(+5.0, 1.0, 0.1, 1.0, 2.0) == 0.0);  // compression weakening
  CHECK(cullen_dehnen_local_alpha(-5.0, 0.0, 0.1, 1.0, 2.0) == 0.0);  // fully limited
  // A = 0.5 * 40 = 20, H^2 A = 0.2, v^2 = 0.04: alpha_max 0.2 / 0.24.
  CHECK(cullen_dehnen_local_alpha(-40.0, 0.5, 0.1, 0.2, 1.5) == Approx(1.5 * 0.2 / 0.24));
  // A strong source saturates at alpha_max.
  CHECK(cullen_dehnen_local_alpha(-1e12, 1.0, 0.1, 1.0, 1.5) == Approx(1.5));
}

TEST_CASE("alpha rises at once and decays on tau = H / (2 l v_sig)", "[viscosity_switch]") {
  viscosity_switch_settings settings;
  settings.alpha_min = 0.05;
  settings.alpha_max = 1.0;
  settings.decay_length = 0.1;
  // Rise: alpha_loc above alpha is taken at once, whatever dt.
  CHECK(cullen_dehnen_alpha(0.1, 0.7, 1e-9, 0.1, 1.0, settings) == 0.7);
  // Decay: tau = 0.1 / (2 0.1 1) = 0.5; after dt = tau the distance to alpha_loc falls by e.
  const double tau = 0.5;
  CHECK(cullen_dehnen_alpha(0.8, 0.2, tau, 0.1, 1.0, settings) == Approx(0.2 + 0.6 * std::exp(-1.0)));
  // Decays towards alpha_loc = 0, held at alpha_min.
  CHECK(cullen_dehnen_alpha(0.8, 0.0, 100 * tau, 0.1, 1.0, settings) == 0.05);
  // alpha_loc above alpha_max is cut.
  CHECK(cullen_dehnen_alpha(0.5, 3.0, 0.0, 0.1, 1.0, settings) == 1.0);
  // No signal velocity: no time scale, alpha kept.
  CHECK(cullen_dehnen_alpha(0.5, 0.1, 1.0, 0.1, 0.0, settings) == 0.5);
  // Two half steps decay as one step (exp is a semigroup): the update does not depend on dt's split.
  const double once = cullen_dehnen_alpha(0.9, 0.1, 0.2, 0.1, 1.0, settings);
  const double twice =
    cullen_dehnen_alpha(cullen_dehnen_alpha(0.9, 0.1, 0.1, 0.1, 1.0, settings), 0.1, 0.1, 0.1, 1.0, settings);
  CHECK(twice == Approx(once).epsilon(1e-14));
}

TEST_CASE("the starting alpha: alpha_max by default, alpha_min as Phantom starts", "[viscosity_switch]") {
  viscosity_switch_settings settings;
  settings.alpha_min = 0.02;
  settings.alpha_max = 1.5;
  CHECK(starting_alpha(settings) == 1.5);
  settings.start = initial_alpha::alpha_min;
  CHECK(starting_alpha(settings) == 0.02);
}

TEST_CASE("d(div v)/dt from the accelerations: div a - tr(grad v grad v)", "[viscosity_switch]") {
  // Homologous flow v = s x (gradient s I) in free motion (a = 0): div v = D s falls as
  // D s / (1 + s t), so d(div v)/dt = -D s^2 at t = 0, which is -tr(grad v grad v).
  const double s = 0.5;
  const double gradient3[3][3] = {{s, 0, 0}, {0, s, 0}, {0, 0, s}};
  CHECK(divergence_rate_from_acceleration<3>(0.0, gradient3) == Approx(-3 * s * s));
  // A pure rotation (antisymmetric gradient, omega = 2) in its centripetal balance, a = -omega^2 x:
  // div a = -2 omega^2 in 2D, tr(grad v grad v) = -2 omega^2, so div v stays 0.
  const double omega = 2.0;
  const double rotation[2][2] = {{0, -omega}, {omega, 0}};
  CHECK(divergence_rate_from_acceleration<2>(-2 * omega * omega, rotation) == Approx(0.0).margin(1e-15));
  // 1D: a compression rate dv/dx = -1 whose acceleration gradient da/dx = -3 steepens it:
  // d(dv/dx)/dt = -3 - 1.
  const double gradient1[1][1] = {{-1.0}};
  CHECK(divergence_rate_from_acceleration<1>(-3.0, gradient1) == Approx(-4.0));
}

TEST_CASE("Price et al. (2018) alpha_loc: min(10 h^2 A / c^2, alpha_max)", "[viscosity_switch]") {
  CHECK(price_local_alpha(+5.0, 1.0, 0.1, 1.0, 1.0) == 0.0);  // compression weakening
  CHECK(price_local_alpha(-5.0, 0.0, 0.1, 1.0, 1.0) == 0.0);  // fully limited
  // A = 0.5 * 4 = 2, 10 h^2 A / c^2 = 10 * 0.01 * 2 / 0.25 = 0.8, below alpha_max.
  CHECK(price_local_alpha(-4.0, 0.5, 0.1, 0.5, 1.0) == Approx(0.8));
  // Linear in the source up to alpha_max, then cut: twice the source gives alpha_max.
  CHECK(price_local_alpha(-8.0, 0.5, 0.1, 0.5, 1.0) == 1.0);
  // No sound speed (cold gas): any growing compression gives alpha_max.
  CHECK(price_local_alpha(-1.0, 1.0, 0.1, 0.0, 1.5) == 1.5);
}
