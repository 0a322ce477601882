// Kick-drift-kick leapfrog (Verlet; e.g. Springel 2005, MNRAS 364, 1105, sec. 4; Price et al.
// 2018, PASA 35, e031, sec. 2.3.1) with a velocity predictor for the forces at the new positions.
//
// One step of length dt, from a_n, du_n (computed at the end of the previous step):
//   kick_drift:  v_half = v + dt/2 a_n,  u_half = u + dt/2 du_n,  x += dt v_half,
//                v = v_half + dt/2 a_n,  u = u_half + dt/2 du_n  (predicted, for the forces)
//   (search, density, EOS, forces at the new positions: a_n+1, du_n+1)
//   kick:        v = v_half + dt/2 a_n+1,  u = u_half + dt/2 du_n+1
// Wall particles never move; each kick instead adds dt/2 a and dt/2 du to their boundary
// impulse and work, the momentum and energy the fluid gave them. The drift adds each particle's
// path length to its `drift` field, which tells when to distribute the particles again.
#pragma once

#include "specialization/sph/model/neighbourhood.hh"
#include "specialization/sph/model/tasks.hh"

#include "flecsi_lite/topology/ntree.hh"

#include <cmath>

namespace flecsph::sph {

/// Brings x back into the periodic box along its periodic axes (a particle moves far less than
/// a period per step).
template<int D>
void wrap_periodic(const tree::domain<D>& space, vector<D>& x) {
  for (int k = 0; k < D; ++k) {
    if (!space.periodic[k]) continue;
    const double period = space.period(k);
    if (x[k] < space.bounds.lo[k])
      x[k] += period;
    else if (x[k] >= space.bounds.hi[k])
      x[k] -= period;
  }
}

/// A wall particle's half kick: it does not move, but the impulse and work the fluid gave it grow
/// by half * a and half * du/dt.
template<int D>
void accumulate_on_wall(double half, const vector<D>& acceleration, double du_dt, vector<D>& impulse, double& work) {
  for (int k = 0; k < D; ++k) impulse[k] += half * acceleration[k];
  work += half * du_dt;
}

/// Moves x by dt * velocity (back into the periodic box) and adds the path length to `path`.
template<int D>
void drift_by(double dt, const vector<D>& velocity, const tree::domain<D>& space, vector<D>& x, double& path) {
  double speed2 = 0;
  for (int k = 0; k < D; ++k) {
    x[k] += dt * velocity[k];
    speed2 += velocity[k] * velocity[k];
  }
  path += dt * std::sqrt(speed2);
  wrap_periodic<D>(space, x);
}

template<int D>
void kick_drift(double dt, tree::domain<D> space, ro<particle_kind> kind, rw<vector<D>> x, rw<vector<D>> v,
                wo<vector<D>> v_half, rw<double> u, wo<double> u_half, ro<vector<D>> acceleration, ro<double> du_dt,
                rw<vector<D>> impulse, rw<double> work, rw<double> drift) {
  const double half = 0.5 * dt;
  flecsi_lite::forall(
    x.size(),
    [&](std::size_t a) {
      const vector<D>& acc = acceleration(a);
      if (kind(a) != particle_kind::fluid) {
        accumulate_on_wall<D>(half, acc, du_dt(a), impulse(a), work(a));
        v_half(a) = v(a);
        u_half(a) = u(a);
        return;
      }
      vector<D> velocity;
      for (int k = 0; k < D; ++k) velocity[k] = v(a)[k] + half * acc[k];
      drift_by<D>(dt, velocity, space, x(a), drift(a));
      v_half(a) = velocity;
      for (int k = 0; k < D; ++k) v(a)[k] = velocity[k] + half * acc[k];
      u_half(a) = u(a) + half * du_dt(a);
      u(a) = u_half(a) + half * du_dt(a);
    },
    "sph::kick_drift");
}

template<int D>
void kick(double dt, ro<particle_kind> kind, ro<vector<D>> v_half, ro<double> u_half, ro<vector<D>> acceleration,
          ro<double> du_dt, wo<vector<D>> v, wo<double> u, rw<vector<D>> impulse, rw<double> work) {
  const double half = 0.5 * dt;
  flecsi_lite::forall(
    v.size(),
    [&](std::size_t a) {
      const vector<D>& acc = acceleration(a);
      if (kind(a) != particle_kind::fluid) {
        accumulate_on_wall<D>(half, acc, du_dt(a), impulse(a), work(a));
        v(a) = v_half(a);
        u(a) = u_half(a);
        return;
      }
      for (int k = 0; k < D; ++k) v(a)[k] = v_half(a)[k] + half * acc[k];
      u(a) = u_half(a) + half * du_dt(a);
    },
    "sph::kick");
}

}  // namespace flecsph::sph
