// Equations of state: pressure laws, c^2 = (dP/drho) at constant entropy by finite differences,
// the first law du = P/rho^2 drho along adiabats, and the run-time choice by name.
#include "specialization/physics/eos.hh"

#include <catch2/catch.hpp>

#include <cmath>
#include <initializer_list>
#include <stdexcept>
#include <string>

using namespace flecsph::physics;

TEST_CASE("ideal gas pressure, sound speed and inverse", "[eos]") {
  const ideal_gas gas{1.4};
  CHECK(gas.pressure(2.0, 3.0) == Approx(0.4 * 2.0 * 3.0));
  CHECK(gas.sound_speed(2.0, 3.0) == Approx(std::sqrt(1.4 * gas.pressure(2.0, 3.0) / 2.0)));
  CHECK(gas.internal_energy(2.0, gas.pressure(2.0, 3.0)) == Approx(3.0));
  // Sod's left state: rho = 1, P = 1 -> u = 2.5, c = sqrt(1.4).
  CHECK(gas.internal_energy(1.0, 1.0) == Approx(2.5));
  CHECK(gas.sound_speed(1.0, 2.5) == Approx(std::sqrt(1.4)));
}

TEST_CASE("ideal gas: c^2 = dP/drho and du = P/rho^2 drho along an adiabat", "[eos]") {
  for (double gamma : {1.4, 5.0 / 3.0, 2.0}) {
    const ideal_gas gas{gamma};
    const double rho0 = 1.3, u0 = 0.7;
    // At constant entropy P ~ rho^gamma, so u = P/((gamma-1) rho) ~ rho^(gamma-1).
    auto u_adiabat = [&](double rho) { return u0 * std::pow(rho / rho0, gamma - 1.0); };
    auto pressure = [&](double rho) { return gas.pressure(rho, u_adiabat(rho)); };
    for (double rho : {0.2, 1.0, 1.3, 7.5}) {
      const double step = 1e-6 * rho;
      const double dP_drho = (pressure(rho + step) - pressure(rho - step)) / (2.0 * step);
      const double du_drho = (u_adiabat(rho + step) - u_adiabat(rho - step)) / (2.0 * step);
      const double c = gas.sound_speed(rho, u_adiabat(rho));
      CHECK(c * c == Approx(dP_drho).epsilon(1e-8));
      CHECK(du_drho == Approx(pressure(rho) / (rho * rho)).epsilon(1e-8));
    }
  }
}

TEST_CASE("polytrope: P = K rho^Gamma, c^2 = dP/drho, consistent u", "[eos]") {
  const polytropic polytrope{100.0, 2.0};
  CHECK(polytrope.pressure(0.1) == Approx(100.0 * 0.01));
  for (double rho : {1e-3, 0.1, 1.0, 4.0}) {
    const double step = 1e-6 * rho;
    const double dP_drho = (polytrope.pressure(rho + step) - polytrope.pressure(rho - step)) / (2.0 * step);
    const double c = polytrope.sound_speed(rho);
    CHECK(c * c == Approx(dP_drho).epsilon(1e-8));
    CHECK(c * c == Approx(polytrope.polytropic_exponent * polytrope.pressure(rho) / rho));
    const double du_drho =
      (polytrope.internal_energy(rho + step) - polytrope.internal_energy(rho - step)) / (2.0 * step);
    CHECK(du_drho == Approx(polytrope.pressure(rho) / (rho * rho)).epsilon(1e-8));
  }
  // A polytrope is an ideal gas on one adiabat: with gamma = Gamma and its own u, same P and c.
  const ideal_gas gas{2.0};
  const double u = polytrope.internal_energy(0.3);
  CHECK(gas.pressure(0.3, u) == Approx(polytrope.pressure(0.3)));
  CHECK(gas.sound_speed(0.3, u) == Approx(polytrope.sound_speed(0.3)));
}

TEST_CASE("isothermal gas: P = c^2 rho and c^2 = dP/drho", "[eos]") {
  const isothermal gas{0.3};
  CHECK(gas.pressure(2.0, 123.0) == Approx(0.09 * 2.0));  // u is ignored
  const double dP_drho = (gas.pressure(2.0 + 1e-6) - gas.pressure(2.0 - 1e-6)) / 2e-6;
  CHECK(gas.sound_speed() * gas.sound_speed() == Approx(dP_drho).epsilon(1e-8));
}

TEST_CASE("run-time equation of state matches each law", "[eos]") {
  equation_of_state eos;
  eos.ideal = {1.4};
  eos.polytrope = {3.0, 1.5};
  eos.constant_temperature = {0.5};
  const double rho = 1.7, u = 0.9;
  eos.type = eos_from_name("ideal_gas");
  CHECK(eos.pressure(rho, u) == eos.ideal.pressure(rho, u));
  CHECK(eos.sound_speed(rho, u) == eos.ideal.sound_speed(rho, u));
  eos.type = eos_from_name("polytropic");
  CHECK(eos.pressure(rho, u) == eos.polytrope.pressure(rho));
  CHECK(eos.sound_speed(rho, u) == eos.polytrope.sound_speed(rho));
  eos.type = eos_from_name("isothermal");
  CHECK(eos.pressure(rho, u) == eos.constant_temperature.pressure(rho));
  CHECK(eos.sound_speed(rho, u) == 0.5);
  for (eos_type type : {eos_type::ideal_gas, eos_type::polytropic, eos_type::isothermal})
    CHECK(eos_from_name(eos_name(type)) == type);
}

TEST_CASE("unknown equation of state is a clear error", "[eos]") {
  try {
    eos_from_name("ideal-gas");
    FAIL("no exception");
  } catch (const std::invalid_argument& error) {
    const std::string message = error.what();
    CHECK(message.find("unknown equation of state 'ideal-gas'") != std::string::npos);
    CHECK(message.find("did you mean 'ideal_gas'") != std::string::npos);
  }
}
