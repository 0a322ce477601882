// Exact Riemann solver: Toro's Tables 4.2-4.3 (Tests 1-5), Rankine-Hugoniot at the Sod shock,
// isentropy and Riemann invariants in the fan, contact conditions, global conservation, vacuum.
#include "specialization/analytic/riemann_exact.hh"

#include "specialization/analytic/quadrature.hh"

#include <catch2/catch.hpp>

#include <cmath>
#include <stdexcept>

using namespace flecsph::analytic;

namespace {

/// Published value with its last printed digit: |value - published| <= half a unit of it, plus
/// 1e-5 relative because Toro's tables come from his iteration with tolerance 1e-6 (Test 5, the
/// strongest, is off by 4e-6 in p*) and from rounded input data (Test 5's states are Test 3's
/// and 4's star states to 6 digits).
void check_published(double value, double published, double last_digit) {
  INFO("computed " << value << ", published " << published);
  CHECK(std::fabs(value - published) <= 0.5 * last_digit + 1e-5 * std::fabs(published));
}

struct toro_test {
  riemann_state left, right;
  double p_star, p_digit, u_star, u_digit, rho_left, rho_left_digit, rho_right, rho_right_digit;
  wave_kind left_wave, right_wave;
};

constexpr double gamma_air = 1.4;

}  // namespace

TEST_CASE("Toro's Tests 1-5: star pressure, velocity and densities", "[riemann]") {
  using wave = wave_kind;
  // Toro (2009), Table 4.1 (initial data), Table 4.2 (p*, u*), Table 4.3 (rho*L, rho*R).
  const toro_test tests[] = {
    {{1.0, 0.0, 1.0},
     {0.125, 0.0, 0.1},
     0.30313,
     1e-5,
     0.92745,
     1e-5,
     0.42632,
     1e-5,
     0.26557,
     1e-5,
     wave::rarefaction,
     wave::shock},
    {{1.0, -2.0, 0.4},
     {1.0, 2.0, 0.4},
     0.00189,
     1e-5,
     0.0,
     1e-5,
     0.02185,
     1e-5,
     0.02185,
     1e-5,
     wave::rarefaction,
     wave::rarefaction},
    {{1.0, 0.0, 1000.0},
     {1.0, 0.0, 0.01},
     460.894,
     1e-3,
     19.5975,
     1e-4,
     0.57506,
     1e-5,
     5.99924,
     1e-5,
     wave::rarefaction,
     wave::shock},
    {{1.0, 0.0, 0.01},
     {1.0, 0.0, 100.0},
     46.0950,
     1e-4,
     -6.19633,
     1e-5,
     5.99242,
     1e-5,
     0.57511,
     1e-5,
     wave::shock,
     wave::rarefaction},
    {{5.99924, 19.5975, 460.894},
     {5.99242, -6.19633, 46.0950},
     1691.64,
     1e-2,
     8.68975,
     1e-5,
     14.2823,
     1e-4,
     31.0426,
     1e-4,
     wave::shock,
     wave::shock},
  };
  int number = 1;
  for (const auto& test : tests) {
    INFO("Toro test " << number++);
    const riemann_solution solution = solve_riemann_problem(test.left, test.right, gamma_air);
    check_published(solution.star_pressure(), test.p_star, test.p_digit);
    check_published(solution.star_velocity(), test.u_star, test.u_digit);
    check_published(solution.star_density_left(), test.rho_left, test.rho_left_digit);
    check_published(solution.star_density_right(), test.rho_right, test.rho_right_digit);
    CHECK(solution.left_wave() == test.left_wave);
    CHECK(solution.right_wave() == test.right_wave);
    CHECK_FALSE(solution.has_vacuum());
    CHECK(solution.iterations() <= 10);
  }
}

TEST_CASE("Sod shock satisfies the Rankine-Hugoniot conditions", "[riemann]") {
  const riemann_state left{1.0, 0.0, 1.0}, right{0.125, 0.0, 0.1};
  const riemann_solution sod = solve_riemann_problem(left, right, gamma_air);
  const double S = sod.speeds().right_head;
  REQUIRE(sod.speeds().right_tail == S);
  const riemann_state behind = sod.sample(S * (1.0 - 1e-12));
  const riemann_state ahead = sod.sample(S * (1.0 + 1e-12));
  CHECK(ahead.rho == right.rho);
  CHECK(behind.rho == Approx(sod.star_density_right()));
  // Fluxes of mass, momentum and energy through the moving shock (shock frame w = v - S).
  auto mass = [&](const riemann_state& q) { return q.rho * (q.v - S); };
  auto momentum = [&](const riemann_state& q) { return q.rho * (q.v - S) * (q.v - S) + q.P; };
  auto enthalpy = [&](const riemann_state& q) {  // h + w^2/2, conserved across the shock
    return specific_internal_energy(q, gamma_air) + q.P / q.rho + 0.5 * (q.v - S) * (q.v - S);
  };
  CHECK(mass(behind) == Approx(mass(ahead)).epsilon(1e-12));
  CHECK(momentum(behind) == Approx(momentum(ahead)).epsilon(1e-12));
  CHECK(enthalpy(behind) == Approx(enthalpy(ahead)).epsilon(1e-12));
  // The shock is faster than sound ahead of it and slower than sound behind it (entropy).
  CHECK(S > right.v + std::sqrt(gamma_air * right.P / right.rho));
  CHECK(S < behind.v + std::sqrt(gamma_air * behind.P / behind.rho));
}

TEST_CASE(
  "Sod rarefaction is isentropic with a constant Riemann invariant; contact is a "
  "pure density jump",
  "[riemann]") {
  const riemann_state left{1.0, 0.0, 1.0}, right{0.125, 0.0, 0.1};
  const riemann_solution sod = solve_riemann_problem(left, right, gamma_air);
  const wave_speeds& speeds = sod.speeds();
  CHECK(speeds.left_head == Approx(-std::sqrt(gamma_air)));
  CHECK(speeds.left_head < speeds.left_tail);
  CHECK(speeds.left_tail < speeds.contact);
  CHECK(speeds.contact < speeds.right_head);
  CHECK(speeds.contact == sod.star_velocity());
  const double entropy = left.P / std::pow(left.rho, gamma_air);
  const double invariant = left.v + 2.0 / (gamma_air - 1.0) * std::sqrt(gamma_air);
  for (int i = 0; i <= 20; ++i) {
    const double s = speeds.left_head + (speeds.left_tail - speeds.left_head) * i / 20.0;
    const riemann_state q = sod.sample(s);
    const double c = std::sqrt(gamma_air * q.P / q.rho);
    CHECK(q.P / std::pow(q.rho, gamma_air) == Approx(entropy).epsilon(1e-12));
    CHECK(q.v + 2.0 / (gamma_air - 1.0) * c == Approx(invariant).epsilon(1e-12));
    CHECK(q.v - c == Approx(s).margin(1e-12));  // the fan is a C- characteristic family
  }
  const riemann_state before = sod.sample(speeds.contact - 1e-12);
  const riemann_state after = sod.sample(speeds.contact + 1e-12);
  CHECK(before.P == after.P);
  CHECK(before.v == after.v);
  CHECK(before.rho == Approx(sod.star_density_left()));
  CHECK(after.rho == Approx(sod.star_density_right()));
  CHECK(sod.sample(-10.0).rho == left.rho);
  CHECK(sod.sample(10.0).rho == right.rho);
  CHECK(sod.at(0.3, 0.2, 0.1).rho == sod.sample(1.0).rho);
}

TEST_CASE("sampled Sod profile conserves mass, momentum and energy", "[riemann]") {
  // In [-1, 1] until t = 0.2 no wave reaches the ends, where v = 0: mass and energy stay,
  // momentum grows by (P_L - P_R) t.
  const riemann_state left{1.0, 0.0, 1.0}, right{0.125, 0.0, 0.1};
  const riemann_solution sod = solve_riemann_problem(left, right, gamma_air);
  const double t = 0.2;
  auto integral = [&](auto density_of) {
    // Panels end at every wave edge so that the rule sees only smooth pieces.
    const wave_speeds& w = sod.speeds();
    const double edges[] = {-1.0, w.left_head * t, w.left_tail * t, w.contact * t, w.right_head * t, 1.0};
    const gauss_legendre_rule rule(10);
    double sum = 0.0;
    for (int i = 0; i + 1 < 6; ++i)
      sum += integrate([&](double x) { return density_of(sod.at(x, t)); }, edges[i], edges[i + 1], 8, rule);
    return sum;
  };
  const double mass = integral([](const riemann_state& q) { return q.rho; });
  const double momentum = integral([](const riemann_state& q) { return q.rho * q.v; });
  const double energy =
    integral([](const riemann_state& q) { return 0.5 * q.rho * q.v * q.v + q.P / (gamma_air - 1.0); });
  CHECK(mass == Approx(1.0 + 0.125).epsilon(1e-12));
  CHECK(momentum == Approx((left.P - right.P) * t).epsilon(1e-12));
  CHECK(energy == Approx((1.0 + 0.1) / (gamma_air - 1.0)).epsilon(1e-12));
}

TEST_CASE("vacuum: generated between two receding gases, and given on one side", "[riemann]") {
  const double gamma = 1.4, g4 = 2.0 / (gamma - 1.0);
  const riemann_state left{1.0, -6.0, 0.4}, right{1.0, 6.0, 0.4};  // 2 (aL+aR)/(g-1) < 12
  const riemann_solution apart = solve_riemann_problem(left, right, gamma);
  const double a = std::sqrt(gamma * 0.4);
  CHECK(apart.has_vacuum());
  CHECK(apart.speeds().left_tail == Approx(-6.0 + g4 * a));
  CHECK(apart.speeds().right_tail == Approx(6.0 - g4 * a));
  CHECK(apart.sample(0.0).rho == 0.0);
  CHECK(apart.sample(0.0).P == 0.0);
  CHECK(apart.sample(-6.0 - a).rho == Approx(1.0));
  CHECK(apart.sample(apart.speeds().left_tail - 1e-9).rho == Approx(0.0).margin(1e-8));

  const riemann_state gas{1.0, 0.0, 1.0}, nothing{0.0, 0.0, 0.0};
  const riemann_solution expansion = solve_riemann_problem(gas, nothing, gamma);
  const double c = std::sqrt(gamma);
  CHECK(expansion.has_vacuum());
  CHECK(expansion.speeds().left_head == Approx(-c));
  CHECK(expansion.speeds().left_tail == Approx(g4 * c));  // the gas front moves at 2c/(g-1)
  CHECK(expansion.sample(g4 * c + 1e-9).rho == 0.0);
  const riemann_state middle = expansion.sample(0.5 * g4 * c);
  CHECK(middle.rho > 0.0);
  CHECK(middle.P / std::pow(middle.rho, gamma) == Approx(1.0).epsilon(1e-12));  // isentropic
  // The mirror image gives the mirrored solution.
  const riemann_solution mirror = solve_riemann_problem(nothing, gas, gamma);
  for (double s : {-5.0, -2.0, -0.3, 0.0, 1.1, 3.0}) CHECK(mirror.sample(s).rho == Approx(expansion.sample(-s).rho));
}

TEST_CASE("invalid Riemann data is rejected", "[riemann]") {
  const riemann_state good{1.0, 0.0, 1.0};
  CHECK_THROWS_AS(solve_riemann_problem(good, good, 1.0), std::invalid_argument);
  CHECK_THROWS_AS(solve_riemann_problem({-1.0, 0.0, 1.0}, good, 1.4), std::invalid_argument);
  CHECK_THROWS_AS(solve_riemann_problem(good, {1.0, 0.0, -0.1}, 1.4), std::invalid_argument);
  CHECK_THROWS_AS(solve_riemann_problem(good, {0.0, 0.0, 1.0}, 1.4), std::invalid_argument);
  CHECK_THROWS_AS(solve_riemann_problem({0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}, 1.4), std::invalid_argument);
  CHECK_THROWS_AS(solve_riemann_problem(good, {1.0, NAN, 1.0}, 1.4), std::invalid_argument);
}
