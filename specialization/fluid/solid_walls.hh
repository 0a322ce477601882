// Solid walls of dummy particles (Adami, Hu & Adams 2012, JCP 231, 7057): each wall particle takes
// the pressure extrapolated from the fluid it sees, with the body force (their eq. 27), the density
// of that pressure by the EOS, and for no-slip walls the velocity 2 v_w - v~ (their eqs. 22-23).
#pragma once

#include "specialization/fluid/fluid_fields.hh"
#include "specialization/fluid/fluid_settings.hh"

#include "specialization/physics/kernels/kernel_at.hh"
#include "specialization/sph/model/neighbourhood.hh"
#include "specialization/sph/model/tasks.hh"

#include "specialization/physics/kernels.hh"

#include "flecsi_lite/execution.hh"

#include <algorithm>
#include <cmath>
#include <vector>

namespace flecsph::fluid {

/// Reads the fluid neighbours' values (ghosts included) and writes the owned wall particles'.
template<class T>
using wall_rw = sph::accessor<T, flecsi_lite::rw, flecsi_lite::ro>;

/// For every owned wall particle w, over its fluid neighbours f (W_wf at h_w, r_wf = x_w - x_f):
///   P_w = [sum_f P_f W_wf + (g - a_w) . sum_f rho_f r_wf W_wf] / sum_f W_wf   (eq. 27, a_w = 0:
///         the walls move at constant velocity)
///   rho_w = rho(P_w) of the Tait EOS, v~_w = sum_f v_f W_wf / sum_f W_wf,
///   v_w (field velocity) = 2 v_prescribed - v~_w for no-slip walls (eq. 23), v_prescribed for
///   free-slip ones (whose pairs then carry no viscous force).
/// A wall particle with no fluid neighbour keeps P_b, rho0 and its prescribed velocity.
template<int D>
void extrapolate_wall_state(sph::neighbours_ro<D> neighbours_object, physics::kernel_type kernel_type,
                            fluid_settings settings, sph::ro_with_ghosts<vector<D>> x,
                            sph::ro_with_ghosts<sph::particle_kind> kind, sph::ro<double> h,
                            sph::ro<vector<D>> prescribed, wall_rw<double> P, wall_rw<double> rho, wall_rw<vector<D>> v,
                            sph::wo<double> sound_speed) {
  const sph::neighbourhood<D>& neighbours = *neighbours_object;
  const sph::neighbour_walk<D> walk(neighbours);
  const bool no_slip = settings.walls == wall_condition::no_slip;
  physics::dispatch_kernel<D>(kernel_type, [&](auto kernel_type_tag) {
    using Kernel = decltype(kernel_type_tag);
    flecsi_lite::forall(
      neighbours.size(),
      [&](std::size_t a) {
        if (kind(a) != sph::particle_kind::wall) return;
        const sph::kernel_at<Kernel> kernel(h(a));
        const double reach2 = physics::kernel_support * physics::kernel_support * h(a) * h(a);
        double weight = 0, pressure = 0, force_term = 0;
        vector<D> velocity{}, r;
        for (std::size_t j = walk.begin(a), end = walk.end(a); j < end; ++j) {
          const std::size_t f = walk.neighbour(j);
          if (kind(f) != sph::particle_kind::fluid) continue;
          const double r2 = walk.separation(x(a), x(f), j, r);
          if (r2 >= reach2) continue;
          double w, dw_dh;
          kernel.value_and_h_derivative(std::sqrt(r2), w, dw_dh);
          weight += w;
          pressure += P(f) * w;
          double g_dot_r = 0;
          for (int k = 0; k < D; ++k) g_dot_r += settings.body_force[k] * r[k];
          force_term += rho(f) * g_dot_r * w;
          for (int k = 0; k < D; ++k) velocity[k] += v(f)[k] * w;
        }
        if (weight > 0) {
          // Never below the background: a wall under tension would pull the fluid onto it.
          P.owned(a) = std::max((pressure + force_term) / weight, settings.eos.background_pressure);
          for (int k = 0; k < D; ++k)
            v.owned(a)[k] = no_slip ? 2 * prescribed(a)[k] - velocity[k] / weight : prescribed(a)[k];
        } else {
          P.owned(a) = settings.eos.background_pressure;
          v.owned(a) = prescribed(a);
        }
        rho.owned(a) = settings.eos.density(P.owned(a));
        sound_speed(a) = settings.eos.sound_speed(rho.owned(a));
      },
      "fluid::extrapolate_wall_state");
  });
}

}  // namespace flecsph::fluid
