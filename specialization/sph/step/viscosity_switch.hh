// The per-particle alpha of the Cullen & Dehnen (2010, MNRAS 408, 669) viscosity switch
// (physics/viscosity_switch.hh) as tasks of the SPH step: the velocity gradient tensor (div v and
// the shear), then per particle the limiter, the rate of change of div v since the particle's
// last update, alpha_loc and the new alpha. Placed between the equation of state and the forces
// (sph_model.hh); the force pass reads alpha_ab = (alpha_a + alpha_b) / 2 (forces.hh).
//
// d(div v)/dt is by default div a - tr(grad v grad v) from the accelerations of the last force
// evaluation (CD10 sec. 2.3; Price et al. 2018, PASA 35, e031, as Phantom), computed in the
// gradient pass; `viscosity_switch_rate = difference` takes instead the difference of div v
// between the particle's updates over the time between them, as SWIFT's SPHENIX does (Borrow et
// al. 2022, MNRAS 511, 2367, sec. 2.4), which reacts one step late at a shock. With individual
// time steps only the active particles are updated, each over its own step.
#pragma once

#include "specialization/physics/kernels/kernel_at.hh"
#include "specialization/sph/model/neighbourhood.hh"
#include "specialization/sph/model/simulation.hh"
#include "specialization/sph/model/tasks.hh"

#include "specialization/physics/kernels.hh"
#include "specialization/physics/viscosity_switch.hh"

#include "flecsi_lite/execution.hh"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <tuple>
#include <vector>

namespace flecsph::sph {

/// div v_a, tr(S_a S_a^T) and d(div v)/dt of the owned targets of one part, S the traceless
/// symmetric part of the SPH velocity gradient dv_k/dx_l = -1/(Omega_a rho_a) sum_b m_b
/// (v_a - v_b)_k r_ab,l F_a (grad_a W_ab = r_ab F_a; Price 2012, JCP 231, 759, eq. 101): its trace
/// is the div v of the density pass (velocity_gradients.hh). div a, the same estimate on the accelerations of
/// the last force evaluation, gives d(div v)/dt = div a - tr(grad v grad v).
template<int D, flecsi_lite::privilege Ghost>
void compute_switch_gradients(neighbours_ro<D> neighbours_object, physics_settings settings,
                              ro_neighbours<vector<D>, Ghost> x, ro_neighbours<vector<D>, Ghost> v,
                              ro_neighbours<vector<D>, Ghost> acceleration, ro_neighbours<double, Ghost> m,
                              ro<double> h, ro<double> rho, ro<double> omega, wo<double> divergence,
                              wo<double> shear_squared, wo<double> divergence_rate) {
  const neighbourhood<D>& neighbours = *neighbours_object;
  const neighbour_walk<D> walk(neighbours);
  const std::vector<std::uint32_t>& targets = neighbours.targets(Ghost);
  physics::dispatch_kernel<D>(settings.kernel, [&](auto kernel) {
    using Kernel = decltype(kernel);
    flecsi_lite::forall(
      targets.size(),
      [&](std::size_t i) {
        const std::size_t a = targets[i];
        const kernel_at<Kernel> kernel_a(h(a));
        const double reach2 = physics::kernel_support * physics::kernel_support * h(a) * h(a);
        double gradient[D][D] = {};
        double acceleration_sum = 0;
        vector<D> r;
        const neighbour_row<D> row = walk.row(a);
        for (std::size_t j = 0, end = row.size(); j < end; ++j) {
          const std::size_t b = row.neighbour(j);
          const double r2 = row.separation(x(a), x(b), j, r);
          if (r2 >= reach2 || r2 == 0) continue;
          const double factor = m(b) * kernel_a.gradient_factor(std::sqrt(r2));
          for (int k = 0; k < D; ++k) {
            for (int l = 0; l < D; ++l) gradient[k][l] += (v(a)[k] - v(b)[k]) * r[l] * factor;
            acceleration_sum += (acceleration(a)[k] - acceleration(b)[k]) * r[k] * factor;
          }
        }
        const double scale = -1.0 / (omega(a) * rho(a));
        double div = 0;
        for (int k = 0; k < D; ++k) div += scale * gradient[k][k];
        double velocity_gradient[D][D];
        for (int k = 0; k < D; ++k)
          for (int l = 0; l < D; ++l) velocity_gradient[k][l] = scale * gradient[k][l];
        divergence_rate(a) = physics::divergence_rate_from_acceleration<D>(scale * acceleration_sum, velocity_gradient);
        double shear = 0;
        for (int k = 0; k < D; ++k)
          for (int l = 0; l < D; ++l) {
            const double S = 0.5 * scale * (gradient[k][l] + gradient[l][k]) - (k == l ? div / D : 0.0);
            shear += S * S;
          }
        divergence(a) = div;
        shear_squared(a) = shear;
      },
      "sph::compute_switch_gradients");
  });
}

/// The new alpha of the owned targets of one part at time `now` (CD10 eqs. 13-18): R_a from the
/// signs of the neighbours' div v (eq. 17), the limiter, d(div v)/dt since the particle's last
/// update (at previous_time, with previous_divergence), v_sig,a = max_b [(c_a + c_b)/2 -
/// min(0, v_ab . r_ab / |r_ab|)] (CD10 eq. 14, at least c_a), H = kernel_support h_a. Then the
/// current div v and `now` become the previous ones.
template<int D, flecsi_lite::privilege Ghost>
void update_switch_alpha(neighbours_ro<D> neighbours_object, physics_settings settings, double now,
                         ro_neighbours<vector<D>, Ghost> x, ro_neighbours<vector<D>, Ghost> v,
                         ro_neighbours<double, Ghost> m, ro_neighbours<double, Ghost> cs,
                         ro_neighbours<double, Ghost> divergence, ro<double> h, ro<double> rho,
                         ro<double> shear_squared, ro<double> divergence_rate, rw<double> alpha,
                         rw<double> previous_divergence, rw<double> previous_time) {
  const neighbourhood<D>& neighbours = *neighbours_object;
  const neighbour_walk<D> walk(neighbours);
  const std::vector<std::uint32_t>& targets = neighbours.targets(Ghost);
  const physics::viscosity_switch_settings& parameters = settings.viscosity_switch;
  physics::dispatch_kernel<D>(settings.kernel, [&](auto kernel) {
    using Kernel = decltype(kernel);
    flecsi_lite::forall(
      targets.size(),
      [&](std::size_t i) {
        const std::size_t a = targets[i];
        const kernel_at<Kernel> kernel_a(h(a));
        const double support_radius = physics::kernel_support * h(a);
        const double reach2 = support_radius * support_radius;
        double signed_sum = 0, signal = cs(a);
        vector<D> r;
        const neighbour_row<D> row = walk.row(a);
        for (std::size_t j = 0, end = row.size(); j < end; ++j) {
          const std::size_t b = row.neighbour(j);
          const double r2 = row.separation(x(a), x(b), j, r);
          if (r2 >= reach2) continue;
          const double distance = std::sqrt(r2);
          double w, dw_dh;
          kernel_a.value_and_h_derivative(distance, w, dw_dh);
          // sign(0) = 0: a neighbour at rest neither compresses nor expands.
          const double sign = divergence(b) > 0 ? 1.0 : (divergence(b) < 0 ? -1.0 : 0.0);
          signed_sum += sign * m(b) * w;
          if (r2 == 0) continue;
          double approach = 0;
          for (int k = 0; k < D; ++k) approach += (v(a)[k] - v(b)[k]) * r[k];
          signal = std::max(signal, 0.5 * (cs(a) + cs(b)) - std::min(0.0, approach / distance));
        }
        const double R = std::clamp(signed_sum / rho(a), -1.0, 1.0);
        const double xi = physics::cullen_dehnen_limiter(divergence(a), shear_squared(a), R);
        const double dt = now - previous_time(a);
        double rate = divergence_rate(a);
        if (parameters.rate == physics::divergence_rate_estimate::difference)
          rate = dt > 0 ? (divergence(a) - previous_divergence(a)) / dt : 0.0;
        const double local =
          parameters.form == physics::local_alpha_form::price
            ? physics::price_local_alpha(rate, xi, h(a), cs(a), parameters.alpha_max)
            : physics::cullen_dehnen_local_alpha(rate, xi, support_radius, signal, parameters.alpha_max);
        alpha(a) = physics::cullen_dehnen_alpha(alpha(a), local, dt, support_radius, signal, parameters);
        previous_divergence(a) = divergence(a);
        previous_time(a) = now;
      },
      "sph::update_switch_alpha");
  });
}

/// At the start of a run: alpha = alpha_max by default (no history of div v tells a shock from a
/// smooth flow yet; it decays within a few sound-crossing times of h where there is none), or
/// alpha_min (`viscosity_switch_start`, Phantom's start: alpha rises at the first update wherever
/// alpha_loc is larger); the current div v and `now` as the previous ones.
template<int D>
void start_switch_alpha(physics_settings settings, double now, ro<double> divergence, wo<double> alpha,
                        wo<double> previous_divergence, wo<double> previous_time) {
  const double start = physics::starting_alpha(settings.viscosity_switch);
  flecsi_lite::forall(
    divergence.size(),
    [&](std::size_t a) {
      alpha(a) = start;
      previous_divergence(a) = divergence(a);
      previous_time(a) = now;
    },
    "sph::start_switch_alpha");
}

/// The time of the state the step is computing: s.time at the start, the end of the step being
/// taken during `advance` (the clock moves after the kick).
template<int D>
double switch_time_now(const simulation<D>& s, bool starting) {
  if (starting) return s.time;
  if (s.physics.individual_time_steps()) return s.clock.time_at(s.clock.next, s.run.end_time);
  return s.time + s.dt;
}

/// The switch's action in the step (a no-op with it off): gradients, then alpha. At the start
/// (`starting`) alpha is set by start_switch_alpha; a restart keeps the checkpoint's.
template<int D>
void update_viscosity_switch(simulation<D>& s, bool starting) {
  if (!s.physics.viscosity_switch.enabled) return;
  if (starting && s.restarted) return;
  using f = fields<D>;
  auto& p = *s.particles;
  std::apply(
    [&](auto... field) {
      flecsi_lite::execute<compute_switch_gradients<D, flecsi_lite::na>>(s.neighbours, s.physics, field...);
      flecsi_lite::execute<compute_switch_gradients<D, flecsi_lite::ro>>(s.neighbours, s.physics, field...);
    },
    std::make_tuple(f::position()(p), f::velocity(p), f::acceleration(p), f::mass()(p), f::smoothing_length()(p),
                    f::density(p), f::omega(p), f::switch_divergence(p), f::switch_shear(p),
                    f::switch_divergence_rate(p)));
  const double now = switch_time_now(s, starting);
  if (starting) {
    flecsi_lite::execute<start_switch_alpha<D>>(s.physics, now, f::switch_divergence(p), f::viscosity_alpha(p),
                                                f::switch_previous_divergence(p), f::switch_previous_time(p));
    return;
  }
  std::apply(
    [&](auto... field) {
      flecsi_lite::execute<update_switch_alpha<D, flecsi_lite::na>>(s.neighbours, s.physics, now, field...);
      flecsi_lite::execute<update_switch_alpha<D, flecsi_lite::ro>>(s.neighbours, s.physics, now, field...);
    },
    std::make_tuple(f::position()(p), f::velocity(p), f::mass()(p), f::sound_speed(p), f::switch_divergence(p),
                    f::smoothing_length()(p), f::density(p), f::switch_shear(p), f::switch_divergence_rate(p),
                    f::viscosity_alpha(p), f::switch_previous_divergence(p), f::switch_previous_time(p)));
}

}  // namespace flecsph::sph
