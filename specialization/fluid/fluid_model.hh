// Weakly compressible SPH for liquids on the standard SPH control model: the app frame's model
// (sph::make_app_control_model) with its physics actions replaced by name, in the same places:
//
//   initialize  search -> density -> equation_of_state (+ walls) -> forces -> first_time_step
//   advance     kick_drift (x, v, rho) -> search -> density -> equation_of_state (+ walls)
//               -> forces (drho/dt, dv/dt) -> kick -> clock
//
// density is the summation only with density_method = summation (else rho comes from the
// continuity equation in the kicks); the walls' state is extrapolated (solid_walls.hh).
#pragma once

#include "specialization/fluid/fluid_fields.hh"
#include "specialization/fluid/fluid_forces.hh"
#include "specialization/fluid/fluid_settings.hh"
#include "specialization/fluid/solid_walls.hh"

#include "specialization/sph/run/app.hh"

#include "flecsi_lite/execution.hh"

#include <cmath>

namespace flecsph::fluid {

/// The state of a fluid run: an SPH app's state with the fluid's settings.
template<int D>
struct fluid_state : sph::app_state<D> {
  fluid_settings fluid;
};

/// First half kick and drift of the leapfrog (sph/integrator.hh) with the density as a third
/// state variable: rho_half = rho + dt/2 drho/dt, then rho predicted to the full step. Walls move
/// with their prescribed velocity (a moving lid) and are never kicked.
template<int D>
void fluid_kick_drift(double dt, sph::tree::domain<D> space, sph::ro<sph::particle_kind> kind, sph::rw<vector<D>> x,
                      sph::rw<vector<D>> v, sph::wo<vector<D>> v_half, sph::rw<double> rho, sph::wo<double> rho_half,
                      sph::ro<vector<D>> acceleration, sph::ro<double> density_rate, sph::ro<vector<D>> wall_velocity,
                      sph::rw<double> drift) {
  const double half = 0.5 * dt;
  flecsi_lite::forall(
    x.size(),
    [&](std::size_t a) {
      const bool fluid = kind(a) == sph::particle_kind::fluid;
      vector<D> velocity;
      double speed2 = 0;
      for (int k = 0; k < D; ++k) {
        velocity[k] = fluid ? v(a)[k] + half * acceleration(a)[k] : wall_velocity(a)[k];
        x(a)[k] += dt * velocity[k];
        speed2 += velocity[k] * velocity[k];
      }
      drift(a) += dt * std::sqrt(speed2);
      sph::wrap_periodic<D>(space, x(a));
      v_half(a) = velocity;
      rho_half(a) = rho(a);
      if (!fluid) return;
      for (int k = 0; k < D; ++k) v(a)[k] = velocity[k] + half * acceleration(a)[k];
      rho_half(a) = rho(a) + half * density_rate(a);
      rho(a) = rho_half(a) + half * density_rate(a);
    },
    "fluid::kick_drift");
}

/// Second half kick: v and (by continuity) rho from the half step with the new rates.
template<int D>
void fluid_kick(double dt, bool continuity, sph::ro<sph::particle_kind> kind, sph::ro<vector<D>> v_half,
                sph::ro<double> rho_half, sph::ro<vector<D>> acceleration, sph::ro<double> density_rate,
                sph::rw<vector<D>> v, sph::rw<double> rho) {
  const double half = 0.5 * dt;
  flecsi_lite::forall(
    v.size(),
    [&](std::size_t a) {
      if (kind(a) != sph::particle_kind::fluid) return;
      for (int k = 0; k < D; ++k) v(a)[k] = v_half(a)[k] + half * acceleration(a)[k];
      if (continuity) rho(a) = rho_half(a) + half * density_rate(a);
    },
    "fluid::kick");
}

/// P and c of the fluid particles by the Tait EOS (walls: extrapolate_wall_state).
template<int D>
void fluid_pressure(physics::tait eos, sph::ro<sph::particle_kind> kind, sph::ro<double> rho, sph::wo<double> P,
                    sph::wo<double> cs) {
  flecsi_lite::forall(
    rho.size(),
    [&](std::size_t a) {
      if (kind(a) != sph::particle_kind::fluid) return;
      P(a) = eos.pressure(rho(a));
      cs(a) = eos.sound_speed(rho(a));
    },
    "fluid::pressure");
}

template<int D>
void update_fluid_pressure(fluid_state<D>& s) {
  using f = sph::fields<D>;
  using ff = fluid_fields<D>;
  auto& p = *s.particles;
  flecsi_lite::execute<fluid_pressure<D>>(s.fluid.eos, f::kind(p), f::density(p), f::pressure(p), f::sound_speed(p));
  flecsi_lite::execute<extrapolate_wall_state<D>>(s.neighbours, s.physics.kernel, s.fluid, f::position()(p), f::kind(p),
                                                  f::smoothing_length()(p), ff::wall_velocity(p), f::pressure(p),
                                                  f::density(p), f::velocity(p), f::sound_speed(p));
}

template<int D>
void update_fluid_rates(fluid_state<D>& s) {
  using f = sph::fields<D>;
  using ff = fluid_fields<D>;
  auto& p = *s.particles;
  s.next_time_step = flecsi_lite::reduce<compute_fluid_rates<D>, flecsi_lite::reduction::min>(
    s.neighbours, s.physics.kernel, s.fluid, s.physics.courant, s.physics.acceleration_factor, f::position()(p),
    f::velocity(p), ff::wall_velocity(p), f::mass()(p), f::smoothing_length()(p), f::density(p), f::pressure(p),
    f::sound_speed(p), f::kind(p), f::acceleration(p), ff::density_rate(p));
}

template<int D>
void update_fluid_density(fluid_state<D>& s) {
  if (s.fluid.density == density_method::summation) sph::update_density<D>(s);
}

/// The app frame's control model (output, checkpoints, statistics) with the fluid's physics
/// actions in place of the gas ones, by name.
template<class State>
flecsi_lite::control::control_model<State> make_fluid_control_model(sph::app_problem<State> problem) {
  constexpr int D = State::dimension;
  using f = sph::fields<D>;
  using ff = fluid_fields<D>;
  auto m = sph::make_app_control_model<State>(std::move(problem));
  m.replace("force_evaluation", "density", [](State& s) { update_fluid_density<D>(s); });
  m.replace("force_evaluation", "equation_of_state", [](State& s) { update_fluid_pressure<D>(s); });
  m.replace("force_evaluation", "forces", [](State& s) { update_fluid_rates<D>(s); });
  m.replace("advance", "kick_drift", [](State& s) {
    auto& p = *s.particles;
    flecsi_lite::execute<fluid_kick_drift<D>>(
      s.dt, p.space(), f::kind(p), f::position()(p), f::velocity(p), f::velocity_half(p), f::density(p),
      ff::density_half(p), f::acceleration(p), ff::density_rate(p), ff::wall_velocity(p), f::drift(p));
  });
  m.replace("advance", "kick", [](State& s) {
    auto& p = *s.particles;
    flecsi_lite::execute<fluid_kick<D>>(s.dt, s.fluid.density == density_method::continuity, f::kind(p),
                                        f::velocity_half(p), ff::density_half(p), f::acceleration(p),
                                        ff::density_rate(p), f::velocity(p), f::density(p));
  });
  return m;
}

}  // namespace flecsph::fluid
