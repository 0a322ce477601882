// Gravitational radiation reaction on the binary before contact: the 2.5PN point-mass term of
// physics/radiation_reaction.hh (Kidder 1995, harmonic gauge) evaluated for the two stars' centres
// of mass and velocities (exact sums by particle id, so the same bits on any number of ranks), and
// added to every particle of each star as that star's share, (m2 / M) a_rr on star 1 and
// -(m1 / M) a_rr on star 2: momentum is conserved and the orbit loses energy at mu v.a_rr, Peters'
// rate on a circle (docs/bns.md explains the choice of the point-mass form over the
// Blanchet-Damour-Schaefer potential). It acts from the release until the separation first falls
// below radiation_reaction_cutoff star radii (contact), then stays off.
//
//   place_radiation_reaction(m);   // "radiation_reaction" after "forces", at t = 0 and every step
//
// The energy and the angular momentum it removed are integrated in time (trapezoid over the
// steps, as the two half kicks apply it): E + radiated_energy is conserved.
#pragma once

#include "bns_diagnostics.hh"

#include "specialization/physics.hh"

#include "flecsi_lite/control.hh"
#include "flecsi_lite/execution.hh"

#include <array>
#include <cmath>
#include <cstdint>

namespace bns {

/// What the radiation reaction did so far.
struct radiation_reaction_record {
  bool applied = false;         ///< added at the last force evaluation
  bool switched_off = false;    ///< the separation fell below the cutoff (contact): off from then on
  double switched_off_at = -1;  ///< the time it did
  double power = 0;             ///< energy removed per time at the last force evaluation, -mu v.a_rr
  double torque = 0;            ///< z angular momentum removed per time, -mu (x x a_rr)_z
  double luminosity = 0;        ///< Peters-Mathews quadrupole luminosity of the centres then
  double radiated_energy = 0;   ///< integral of power over the steps taken
  double radiated_angular_momentum = 0;
};

/// Adds each star's share of the radiation-reaction acceleration to its particles.
inline void add_star_accelerations(std::array<vec, 2> share, std::uint64_t first_star_end, sph::ro<std::uint64_t> id,
                                   sph::ro<sph::particle_kind> kind, sph::rw<vec> a) {
  flecsi_lite::forall(
    a.size(),
    [&](std::size_t p) {
      if (kind(p) != sph::particle_kind::fluid) return;
      const vec& added = share[static_cast<std::size_t>(star_of(id(p), first_star_end))];
      for (int k = 0; k < 3; ++k) a(p)[k] += added[k];
    },
    "bns::radiation_reaction");
}

/// Collective: evaluates and adds the radiation reaction when `active` (and the stars are still
/// apart), and integrates the energy and angular momentum removed over the step `dt` just taken
/// (dt = 0 at t = 0). The state's fields are those of the force evaluation: positions at the new
/// time, velocities predicted there.
template<class State>
void apply_radiation_reaction(State& s, radiation_reaction_record& record, bool active, double dt) {
  const double previous_power = record.power, previous_torque = record.torque;
  record.applied = false;
  record.power = record.torque = record.luminosity = 0;
  if (active && !record.switched_off) {
    const auto stars = measure_stars(s, s.first_star_end);
    vec x{}, v{};
    for (int k = 0; k < 3; ++k) {
      x[k] = stars.centre[0][k] - stars.centre[1][k];
      v[k] = stars.velocity[0][k] - stars.velocity[1][k];
    }
    const double separation = std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
    if (separation < s.problem.radiation_reaction_cutoff * s.problem.radius) {
      record.switched_off = true;
      record.switched_off_at = s.time;
    } else {
      const double m1 = stars.mass[0], m2 = stars.mass[1], M = m1 + m2, mu = m1 * m2 / M, c = s.problem.speed_of_light;
      const auto relative = flecsph::physics::radiation_reaction_acceleration(x, v, s.G, m1, m2, c);
      std::array<vec, 2> share{};
      for (int k = 0; k < 3; ++k) share[0][k] = m2 / M * relative[k], share[1][k] = -m1 / M * relative[k];
      auto& p = *s.particles;
      using f = sph::fields<3>;
      flecsi_lite::execute<add_star_accelerations>(share, s.first_star_end, f::id()(p), f::kind(p), f::acceleration(p));
      record.applied = true;
      record.power = -mu * (v[0] * relative[0] + v[1] * relative[1] + v[2] * relative[2]);
      record.torque = -mu * (x[0] * relative[1] - x[1] * relative[0]);
      record.luminosity = flecsph::physics::quadrupole_luminosity(x, v, s.G, m1, m2, c);
    }
  }
  // Each half kick of the step applied the acceleration of one end of it.
  record.radiated_energy += 0.5 * dt * (previous_power + record.power);
  record.radiated_angular_momentum += 0.5 * dt * (previous_torque + record.torque);
}

/// Places "radiation_reaction" in the force evaluation after "forces" (which wrote the
/// acceleration it adds to): at t = 0 and in every step, active once the relaxation is over when
/// the problem asks for it.
template<class State>
void place_radiation_reaction(flecsi_lite::control::control_model<State>& m) {
  m.action("force_evaluation", "radiation_reaction",
           [](State& s) {
             apply_radiation_reaction(s, s.radiation_reaction, s.problem.radiation_reaction && !s.relaxing,
                                      s.initializing ? 0.0 : s.dt);
           })
    .after("forces");
}

}  // namespace bns
