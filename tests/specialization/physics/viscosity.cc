// Artificial viscosity Pi_ab (seed 1.10-1.11), Balsara switch, signal velocity (and the Courant
// step it gives, time_step.hh) and artificial conductivity: zero where they must be, pair symmetry, and values computed by hand.
#include "specialization/physics/viscosity.hh"
#include "specialization/physics/time_step.hh"

#include <catch2/catch.hpp>

#include <array>
#include <cmath>

using namespace flecsph::physics;

namespace {

using vector3 = std::array<double, 3>;

double dot(const vector3& x, const vector3& y) { return x[0] * y[0] + x[1] * y[1] + x[2] * y[2]; }
vector3 difference(const vector3& x, const vector3& y) { return {x[0] - y[0], x[1] - y[1], x[2] - y[2]}; }

/// Pi_ab for particles at positions/velocities (x_a, v_a), (x_b, v_b).
double pair_viscosity(const viscosity_parameters& parameters, const vector3& x_a, const vector3& v_a,
                      const viscosity_particle& a, const vector3& x_b, const vector3& v_b,
                      const viscosity_particle& b) {
  const vector3 r = difference(x_a, x_b), v = difference(v_a, v_b);
  return artificial_viscosity(parameters, dot(r, v), dot(r, r), a, b);
}

}  // namespace

TEST_CASE("viscosity vanishes for receding and for sliding pairs", "[viscosity]") {
  const viscosity_parameters parameters;
  const viscosity_particle a{1.0, 1.0, 0.1}, b{1.2, 0.8, 0.12};
  // receding: r_ab . v_ab > 0
  CHECK(pair_viscosity(parameters, {0.1, 0, 0}, {1, 0, 0}, a, {0, 0, 0}, {0, 0, 0}, b) == 0.0);
  // sliding past each other: r_ab . v_ab = 0
  CHECK(pair_viscosity(parameters, {0.1, 0, 0}, {0, 1, 0}, a, {0, 0, 0}, {0, -1, 0}, b) == 0.0);
  // approaching: positive (dissipative)
  CHECK(pair_viscosity(parameters, {0.1, 0, 0}, {-1, 0, 0}, a, {0, 0, 0}, {0, 0, 0}, b) > 0.0);
}

TEST_CASE("viscosity is symmetric under a <-> b", "[viscosity]") {
  const viscosity_parameters parameters{1.3, 2.1, 0.01};
  const viscosity_particle a{1.0, 1.1, 0.1, 0.7}, b{2.5, 0.4, 0.17, 0.2};
  const vector3 x_a{0.03, -0.02, 0.05}, v_a{-0.4, 0.9, -1.1};
  const vector3 x_b{0.07, 0.01, -0.02}, v_b{0.3, -0.2, 0.8};
  const double ab = pair_viscosity(parameters, x_a, v_a, a, x_b, v_b, b);
  const double ba = pair_viscosity(parameters, x_b, v_b, b, x_a, v_a, a);
  CHECK(ab > 0.0);
  CHECK(ab == ba);
}

TEST_CASE("viscosity matches a hand computation", "[viscosity]") {
  // h = (0.1 + 0.2)/2 = 0.15, c = (1 + 2)/2 = 1.5, rho = (1 + 3)/2 = 2; r = (0.1,0,0),
  // v = (-1,0,0): r.v = -0.1, r^2 = 0.01.
  // mu = 0.15 (-0.1) / (0.01 + 0.01 * 0.15^2) = -0.015 / 0.010225 = -1.466992665036675
  // Pi = (-1 * 1.5 * mu + 2 * mu^2) / 2 = 3.252311978048912
  const viscosity_parameters parameters{1.0, 2.0, 0.01};
  const viscosity_particle a{1.0, 1.0, 0.1}, b{3.0, 2.0, 0.2};
  CHECK(viscosity_mu(0.15, -0.1, 0.01, 0.01) == Approx(-1.466992665036675).epsilon(1e-14));
  CHECK(artificial_viscosity(parameters, -0.1, 0.01, a, b) == Approx(3.252311978048912).epsilon(1e-14));
  // The Balsara factors scale Pi by their mean.
  const viscosity_particle a_switched{1.0, 1.0, 0.1, 0.2}, b_switched{3.0, 2.0, 0.2, 0.6};
  CHECK(artificial_viscosity(parameters, -0.1, 0.01, a_switched, b_switched) ==
        Approx(0.4 * 3.252311978048912).epsilon(1e-14));
}

TEST_CASE("Balsara switch: 1 in pure compression, 0 in pure shear", "[viscosity]") {
  const double c = 1.0, h = 0.01;
  CHECK(balsara_switch(-50.0, 0.0, c, h) == Approx(50.0 / (50.0 + 1e-2)));
  CHECK(balsara_switch(0.0, 30.0, c, h) == 0.0);
  CHECK(balsara_switch(-2.0, 6.0, c, h) == Approx(2.0 / (2.0 + 6.0 + 1e-2)));
  CHECK(balsara_switch(2.0, -6.0, c, h) == balsara_switch(-2.0, 6.0, c, h));
  CHECK(balsara_switch(0.0, 0.0, 0.0, h) == 0.0);  // no 0/0
}

TEST_CASE("signal velocity and Courant time step", "[viscosity]") {
  // receding or at rest: c_a + c_b
  CHECK(signal_velocity(1.0, 2.0, 0.5, 0.1) == 3.0);
  CHECK(signal_velocity(1.0, 2.0, 0.0, 0.0) == 3.0);  // coincident particles: no 0/0
  // approaching at w = r.v/|r| = -0.4/0.2 = -2: 1 + 2 - 3 (-2) = 9
  CHECK(signal_velocity(1.0, 2.0, -0.4, 0.2) == Approx(9.0));
  CHECK(signal_velocity(1.0, 2.0, -0.4, 0.2, 2.0) == Approx(7.0));
  CHECK(courant_time_step(0.3, 0.01, 9.0) == Approx(0.3 * 0.01 / 9.0));
}

TEST_CASE("artificial conductivity: hand value, antisymmetry, heat flows downhill", "[viscosity]") {
  // v_sig^u = sqrt(|2 - 0.5| / 1.5) = 1; term = 0.8 * 1 * (3 - 1) / 1.5 * (-2) = -2.1333...
  CHECK(conductivity_signal_velocity(2.0, 0.5, 1.0, 2.0) == Approx(1.0));
  const double ab = artificial_conductivity(0.8, 3.0, 1.0, 2.0, 0.5, 1.0, 2.0, -2.0);
  const double ba = artificial_conductivity(0.8, 1.0, 3.0, 0.5, 2.0, 2.0, 1.0, -2.0);
  CHECK(ab == Approx(-2.1333333333333333).epsilon(1e-14));
  // Antisymmetric, so m_a du_a + m_b du_b = m_a m_b (ab + ba) = 0: energy is conserved.
  CHECK(ab == -ba);
  CHECK(ab < 0.0);  // the hotter particle a cools
  // No flux without a temperature difference, nor without a pressure difference (Price 2008).
  CHECK(artificial_conductivity(0.8, 2.0, 2.0, 2.0, 0.5, 1.0, 2.0, -2.0) == 0.0);
  CHECK(artificial_conductivity(0.8, 3.0, 1.0, 1.0, 1.0, 1.0, 2.0, -2.0) == 0.0);
}
