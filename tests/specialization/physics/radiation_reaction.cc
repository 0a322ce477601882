// Radiation reaction of two point masses (physics/radiation_reaction.hh): on a circular orbit the
// energy and angular momentum it removes are Peters' (1964) rates and the Peters-Mathews
// luminosity; two point masses integrated (Newton plus the 2.5PN term, fourth-order Runge-Kutta)
// spiral in as Peters' a(t)^4 = a0^4 - (256/5) G^3 m1 m2 M t / c^5, and their Newtonian energy
// falls by exactly the work of the term.
#include "specialization/physics/radiation_reaction.hh"

#include <catch2/catch.hpp>

#include <array>
#include <cmath>

using namespace flecsph::physics;

namespace {
const double G = 1.7, m1 = 1.4, m2 = 0.9, c = 10.0;
const double M = m1 + m2, mu = m1 * m2 / M;

double dot(const vector3& a, const vector3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
double norm(const vector3& a) { return std::sqrt(dot(a, a)); }

/// The relative orbit: x, v and the work done on it by the radiation reaction.
struct orbit {
  vector3 x, v;
  double work = 0;
};

/// d/dt of (x, v, work): Newton plus the radiation reaction.
orbit rate(const orbit& o) {
  const double r = norm(o.x);
  const vector3 rr = radiation_reaction_acceleration(o.x, o.v, G, m1, m2, c);
  orbit d;
  d.x = o.v;
  for (int k = 0; k < 3; ++k) d.v[k] = -G * M * o.x[k] / (r * r * r) + rr[k];
  d.work = mu * dot(o.v, rr);
  return d;
}

orbit advanced(const orbit& o, const orbit& d, double dt) {
  orbit next = o;
  for (int k = 0; k < 3; ++k) next.x[k] += dt * d.x[k], next.v[k] += dt * d.v[k];
  next.work += dt * d.work;
  return next;
}

void runge_kutta_step(orbit& o, double dt) {
  const orbit k1 = rate(o), k2 = rate(advanced(o, k1, dt / 2)), k3 = rate(advanced(o, k2, dt / 2)),
              k4 = rate(advanced(o, k3, dt));
  for (int k = 0; k < 3; ++k) {
    o.x[k] += dt / 6 * (k1.x[k] + 2 * k2.x[k] + 2 * k3.x[k] + k4.x[k]);
    o.v[k] += dt / 6 * (k1.v[k] + 2 * k2.v[k] + 2 * k3.v[k] + k4.v[k]);
  }
  o.work += dt / 6 * (k1.work + 2 * k2.work + 2 * k3.work + k4.work);
}

double newtonian_energy(const orbit& o) { return 0.5 * mu * dot(o.v, o.v) - G * M * mu / norm(o.x); }
}  // namespace

TEST_CASE("on a circular orbit the radiation reaction removes Peters' energy and angular momentum", "[gw]") {
  for (const double a : {0.7, 1.0, 3.3}) {
    const double speed = std::sqrt(G * M / a);
    // An arbitrary orientation of the orbit's plane.
    const vector3 x{a * 0.6, a * 0.8, 0.0}, v{-speed * 0.8 * 0.6, speed * 0.6 * 0.6, speed * 0.8};
    const vector3 rr = radiation_reaction_acceleration(x, v, G, m1, m2, c);
    const double c5 = std::pow(c, 5);
    const double peters_power = 32.0 / 5.0 * std::pow(G, 4) * m1 * m1 * m2 * m2 * M / (c5 * std::pow(a, 5));
    const double peters_torque =
      32.0 / 5.0 * std::pow(G, 3.5) * m1 * m1 * m2 * m2 * std::sqrt(M) / (c5 * std::pow(a, 3.5));
    CHECK(mu * dot(v, rr) == Approx(-peters_power).epsilon(1e-12));
    const vector3 torque{x[1] * rr[2] - x[2] * rr[1], x[2] * rr[0] - x[0] * rr[2], x[0] * rr[1] - x[1] * rr[0]};
    CHECK(mu * norm(torque) == Approx(peters_torque).epsilon(1e-12));
    // A pure drag: anti-parallel to v.
    CHECK(dot(rr, v) == Approx(-norm(rr) * norm(v)).epsilon(1e-12));
    CHECK(quadrupole_luminosity(x, v, G, m1, m2, c) == Approx(peters_power).epsilon(1e-12));
  }
}

TEST_CASE("Peters' a(t) and the time to a given separation", "[gw]") {
  const double a0 = 2.0, beta = 64.0 / 5.0 * G * G * G * m1 * m2 * M / std::pow(c, 5);
  CHECK(peters_rate(G, m1, m2, c) == Approx(beta).epsilon(1e-14));
  const double t = peters_time(a0, 1.5, G, m1, m2, c);
  CHECK(peters_separation(a0, t, G, m1, m2, c) == Approx(1.5).epsilon(1e-12));
  CHECK(peters_separation(a0, peters_time(a0, 0, G, m1, m2, c) * 1.01, G, m1, m2, c) == 0);
  // da/dt = -beta / a^3 at a0.
  const double h = 1e-6 * t;
  CHECK((peters_separation(a0, h, G, m1, m2, c) - a0) / h == Approx(-beta / (a0 * a0 * a0)).epsilon(1e-5));
}

TEST_CASE("two point masses with the radiation reaction spiral in as Peters' a(t)", "[gw]") {
  const double a0 = 1.0;
  const double speed = std::sqrt(G * M / a0);
  orbit o{{a0, 0, 0}, {0, speed, 0}};
  const double energy0 = newtonian_energy(o);
  const double a_end = 0.5 * a0;
  const double period0 = 2 * std::acos(-1.0) * std::sqrt(a0 * a0 * a0 / (G * M));
  const double t_end = peters_time(a0, a_end, G, m1, m2, c);
  REQUIRE(t_end > 30 * period0);  // adiabatic: many orbits
  // Steps of 1/4000 of the current period.
  double t = 0, largest_error = 0;
  while (norm(o.x) > a_end) {
    const double r = norm(o.x);
    const double dt = 2.5e-4 * 2 * std::acos(-1.0) * std::sqrt(r * r * r / (G * M));
    runge_kutta_step(o, dt);
    t += dt;
    const double peters = peters_separation(a0, t, G, m1, m2, c);
    if (peters > a_end) largest_error = std::max(largest_error, std::fabs(norm(o.x) / peters - 1));
  }
  INFO("inspiral to a0 / 2 in " << t << ", Peters " << t_end << "; largest |a / a_Peters - 1| " << largest_error);
  CHECK(t == Approx(t_end).epsilon(1e-4));  // reached 3.3e-6
  CHECK(largest_error < 3e-3);              // reached 9.3e-4: the small eccentricity of a circular start
  // The orbit's Newtonian energy fell by the work of the radiation reaction.
  CHECK(newtonian_energy(o) - energy0 == Approx(o.work).epsilon(1e-8));
  CHECK(o.work < 0);
}
