// Solid walls of dummy particles (Adami, Hu & Adams 2012, JCP 231, 7057): each wall particle takes
// the pressure extrapolated from the fluid it sees, with the body force (their eq. 27), the density
// of that pressure by the EOS, and for no-slip walls the velocity 2 v_w - v~ (their eqs. 22-23).
#pragma once

#include "specialization/fluid/fluid_fields.hh"
#include "specialization/fluid/fluid_settings.hh"

#include "specialization/physics/kernels/kernel_at.hh"
#include "specialization/sph/model/neighbourhood.hh"
#include "specialization/sph/model/tasks.hh"

#include "specialization/numerics/ordered_sum.hh"
#include "specialization/numerics/simd.hh"
#include "specialization/physics/kernels.hh"

#include "flecsi_lite/execution.hh"

#include <algorithm>
#include <cmath>
#include <vector>

namespace flecsph::fluid {

/// Reads the fluid neighbours' values (ghosts included) and writes the owned wall particles'.
template<class T>
using wall_rw = sph::accessor<T, flecsi_lite::rw, flecsi_lite::ro>;

namespace detail {
/// The sums of a wall particle's extrapolation over its fluid neighbours f within its kernel
/// (W_wf at the wall's h, r_wf = x_w - x_f): sum W, sum P_f W, sum rho_f (g . r_wf) W, sum v_f W.
template<int D>
struct wall_sums {
  double weight = 0, pressure = 0, force_term = 0;
  vector<D> velocity{};
};

/// The arrays wall_sums_of reads (owned and ghost particles).
template<int D>
struct wall_fields {
  const vector<D>*x, *v;
  const double *P, *rho;
  const sph::particle_kind* kind;
};

/// wall_sums of wall particle a with kernel h_a. T is the number type of the pair arithmetic
/// (numerics/simd.hh): entries that are walls, beyond the kernel or beyond the list are lanes
/// whose terms are zeroed; the terms go to ordered sums in list order, so the sums are bitwise
/// those of T = double, the loop as it was before packs (tests/specialization/fluid).
template<class Kernel, int D, class T = physics::simd::pack>
wall_sums<D> wall_sums_of(const sph::neighbour_walk<D>& walk, std::size_t a, double h_a, const wall_fields<D>& in,
                          const fluid_settings& settings) {
  namespace simd = physics::simd;
  constexpr std::size_t W = simd::lanes<T>;
  const sph::kernel_at<Kernel> kernel(h_a);
  const double reach2 = physics::kernel_support * physics::kernel_support * h_a * h_a;
  const T zero = 0.0;
  simd::ordered_sum<T> weight, pressure, force_term, velocity[D];
  const vector<D> x_a = in.x[a];
  const sph::neighbour_row<D> row = walk.row(a);
  const std::size_t end = row.size();
  for (std::size_t j0 = 0; j0 < end; j0 += W) {
    // Most of a wall particle's neighbours are walls: their packs are skipped before any arithmetic.
    bool fluid[W], any_fluid = false;
    for (std::size_t i = 0; i < W; ++i) {
      fluid[i] = j0 + i < end && in.kind[row.neighbour(j0 + i)] == sph::particle_kind::fluid;
      any_fluid |= fluid[i];
    }
    if (!any_fluid) continue;
    std::size_t b[W];
    T r[D];
    const T r2 = row.separations(j0, x_a, in.x, b, r);
    const T fluid_lane = simd::generate<T>([&](std::size_t i) { return fluid[i] ? 1.0 : 0.0; });
    const auto pair = (fluid_lane != 0.0) && (r2 < reach2);
    if (!simd::any_lane(pair)) continue;
    // Fluid values only: the other walls' values are being written by this task.
    const auto gather = [&](const double* field) {
      return simd::generate<T>([&](std::size_t i) { return fluid[i] ? field[b[i]] : 0.0; });
    };
    T w, dw_dh;
    kernel.value_and_h_derivative(simd::square_root(r2), w, dw_dh);
    weight.add(simd::select(pair, w, zero));
    pressure.add(simd::select(pair, gather(in.P) * w, zero));
    T g_dot_r = 0.0;
    for (int k = 0; k < D; ++k) g_dot_r += settings.body_force[k] * r[k];
    force_term.add(simd::select(pair, gather(in.rho) * g_dot_r * w, zero));
    for (int k = 0; k < D; ++k)
      velocity[k].add(
        simd::select(pair, simd::generate<T>([&](std::size_t i) { return fluid[i] ? in.v[b[i]][k] : 0.0; }) * w, zero));
  }
  wall_sums<D> sums;
  sums.weight = weight.total();
  sums.pressure = pressure.total();
  sums.force_term = force_term.total();
  for (int k = 0; k < D; ++k) sums.velocity[k] = velocity[k].total();
  return sums;
}
}  // namespace detail

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
  const detail::wall_fields<D> in{x.data(), v.data(), P.data(), rho.data(), kind.data()};
  physics::dispatch_kernel<D>(kernel_type, [&](auto kernel_type_tag) {
    using Kernel = decltype(kernel_type_tag);
    flecsi_lite::forall(
      neighbours.size(),
      [&](std::size_t a) {
        if (kind(a) != sph::particle_kind::wall) return;
        const detail::wall_sums<D> sums = detail::wall_sums_of<Kernel, D>(walk, a, h(a), in, settings);
        const double weight = sums.weight;
        if (weight > 0) {
          // Never below the background: a wall under tension would pull the fluid onto it.
          P.owned(a) = std::max((sums.pressure + sums.force_term) / weight, settings.eos.background_pressure);
          for (int k = 0; k < D; ++k)
            v.owned(a)[k] = no_slip ? 2 * prescribed(a)[k] - sums.velocity[k] / weight : prescribed(a)[k];
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
