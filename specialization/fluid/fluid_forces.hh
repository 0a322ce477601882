// The rates of weakly compressible SPH for a fluid particle: drho/dt by the continuity equation
// with delta-SPH diffusion (Molteni & Colagrossi 2009, CPC 180, 861; the hydrostatic part removed
// as in Antuono et al. 2012, CPC 183, 2570 and Fourtakas et al. 2019, Comput. Fluids 190, 346),
// the pressure force, laminar (Morris, Fox & Zhu 1997, JCP 136, 214) or artificial (Monaghan
// 1992) viscosity, the body force, and the time step from c0, h^2 / nu and the acceleration.
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
#include <limits>
#include <vector>

namespace flecsph::fluid {

namespace detail {
/// The arrays the rates read (owned and ghost particles); inverse_h is 1/h of each (once per
/// particle, not once per pair: the same bits as the 1/h a pair's kernel_at computes).
template<int D>
struct rate_fields {
  const vector<D>*x, *v, *wall_velocity;
  const double *m, *h, *inverse_h, *rho, *P, *cs;
  const sph::particle_kind* kind;
};

/// 1 in the lanes whose neighbour is a wall (any kind but fluid), 0 in the others.
template<class T, std::size_t W>
FLECSPH_SIMD_INLINE T wall_lanes(const sph::particle_kind* kind, const std::size_t (&b)[W]) {
  return physics::simd::generate<T>([&](std::size_t i) { return kind[b[i]] != sph::particle_kind::fluid ? 1.0 : 0.0; });
}

/// dv_a/dt and drho_a/dt over a's list; for a pair (a, b), r = x_a - x_b, grad_a W = F r,
/// F = (F(h_a) + F(h_b)) / 2, V_b = m_b / rho_b:
///   dv/dt   = -sum_b m_b (P_a + P_b) / (rho_a rho_b) F r                                  (pressure)
///           + sum_b m_b 2 mu r^2 F / (rho_a rho_b (r^2 + 0.001 h^2)) v_ab              (Morris eq. 8)
///           or -sum_b m_b Pi_ab F r with Pi_ab = -alpha h c_ab (v_ab . r) / (rho_ab (r^2 + 0.01 h^2))
///           + g
///   drho/dt = rho_a sum_b V_b (v_a - v_b) . r F                                      (continuity)
///           + delta h c0 sum_fluid b V_b 2 (rho_b^H - rho_b) F                          (delta-SPH)
/// where rho_b^H = rho_a - rho0 (g . r) / c_a^2 is the density that hydrostatics gives at b seen
/// from a, so the diffusion vanishes on the hydrostatic state. Walls enter with their
/// extrapolated P, rho and (no-slip) velocity, the continuity sum with their own velocity.
///
/// T is the number type of the pair arithmetic (numerics/simd.hh): a pack takes lanes<T> list
/// entries at once; entries beyond the kernel, beyond the list or at r = 0 are lanes whose terms
/// are zeroed, and a lane's choices (wall or fluid, approaching or not) are selects of terms
/// computed by the scalar expressions. The terms go to ordered sums in list order, so the rates
/// are bitwise those of T = double, the loop as it was before packs (tests/specialization/fluid).
template<class Kernel, int D, class T = physics::simd::pack>
void fluid_rates(const sph::neighbour_walk<D>& walk, std::size_t a, const rate_fields<D>& in,
                 const fluid_settings& settings, bool summation, vector<D>& dv_dt, double& drho_dt) {
  namespace simd = physics::simd;
  constexpr std::size_t W = simd::lanes<T>;
  const double support2 = physics::kernel_support * physics::kernel_support;
  const vector<D> x_a = in.x[a], v_a = in.v[a];
  const double h_a = in.h[a], rho_a = in.rho[a], P_a = in.P[a], c_a = in.cs[a];
  const sph::kernel_at<Kernel> kernel_a(h_a);
  const double mu2 = 2 * settings.dynamic_viscosity;
  const bool laminar = settings.viscosity == viscosity_model::laminar;
  const bool wall_viscosity = settings.walls == wall_condition::no_slip;
  const double diffusion = summation ? 0.0 : settings.delta * h_a * settings.eos.reference_sound_speed;
  const double rho0 = settings.eos.reference_density;
  const T lane = simd::generate<T>([](std::size_t i) { return double(i); }), zero = 0.0;
  simd::ordered_sum<T> sum_v[D], sum_rho, sum_delta;
  const sph::neighbour_row<D> row = walk.row(a);
  const std::size_t end = row.size();
  for (std::size_t j0 = 0; j0 < end; j0 += W) {
    // Lane i holds entry j0 + i; past the end it repeats the last entry, masked out below.
    std::size_t b[W];
    T r[D];
    const T r2 = row.separations(j0, x_a, in.x, b, r);
    const auto gather = [&](const double* field) {
      return simd::generate<T>([&](std::size_t i) { return field[b[i]]; });
    };
    const T h_b = gather(in.h), h_max = simd::maximum(T(h_a), h_b);
    const auto pair = (lane < double(end - j0)) && !(r2 >= support2 * h_max * h_max) && (r2 != 0.0);
    if (!simd::any_lane(pair)) continue;
    const T distance = simd::square_root(r2);
    const T F = 0.5 * (kernel_a.gradient_factor(distance) +
                       sph::kernel_at<Kernel, T>(h_b, gather(in.inverse_h)).gradient_factor(distance));
    const T rho_b = gather(in.rho), m_b = gather(in.m), volume_b = m_b / rho_b;
    const auto wall = wall_lanes<T>(in.kind, b) != 0.0;
    T pressure_pair = -m_b * (P_a + gather(in.P)) / (rho_a * rho_b) * F;  // times r
    T v_ab[D], v_dot_r = 0.0;
    for (int k = 0; k < D; ++k) {
      v_ab[k] = v_a[k] - simd::generate<T>([&](std::size_t i) { return in.v[b[i]][k]; });
      v_dot_r += v_ab[k] * r[k];
    }
    // Morris et al. soften r^2 by 0.01 h^2; at h = 1.5 dx that weakens the lattice's Laplacian by
    // 1.5% (the Poiseuille profile then runs 1.7% fast), 0.001 h^2 by 0.4%. Particles never meet.
    const T h_ab = 0.5 * (h_a + h_b);
    const auto viscous = wall_viscosity ? pair : (pair && !wall);
    T laminar_factor = zero;
    if (laminar) {
      const T laminar_softening = 0.001 * h_ab * h_ab;
      laminar_factor = simd::select(viscous, m_b * mu2 * r2 * F / (rho_a * rho_b * (r2 + laminar_softening)), zero);
    } else {
      const T softening = 0.01 * h_ab * h_ab;
      const T Pi = -settings.artificial_alpha * h_ab * 0.5 * (c_a + gather(in.cs)) * v_dot_r /
                   (0.5 * (rho_a + rho_b) * (r2 + softening));
      pressure_pair = simd::select(viscous && (v_dot_r < 0.0), pressure_pair - m_b * Pi * F, pressure_pair);
    }
    for (int k = 0; k < D; ++k) sum_v[k].add(simd::select(pair, pressure_pair * r[k] + laminar_factor * v_ab[k], zero));
    // Continuity with the wall's own velocity (its `velocity` is the no-slip extrapolation).
    T continuity = v_dot_r;
    if (simd::any_lane(wall)) {
      T wall_continuity = 0.0;
      for (int k = 0; k < D; ++k)
        wall_continuity +=
          (v_a[k] - simd::generate<T>([&](std::size_t i) { return in.wall_velocity[b[i]][k]; })) * r[k];
      continuity = simd::select(wall, wall_continuity, v_dot_r);
    }
    sum_rho.add(simd::select(pair, volume_b * continuity * F, zero));
    if (diffusion > 0) {
      T g_dot_r = 0.0;
      for (int k = 0; k < D; ++k) g_dot_r += settings.body_force[k] * r[k];
      const T hydrostatic_b = rho_a - rho0 * g_dot_r / (c_a * c_a);
      sum_delta.add(simd::select(pair && !wall, volume_b * 2 * (hydrostatic_b - rho_b) * F, zero));
    }
  }
  for (int k = 0; k < D; ++k) dv_dt[k] = sum_v[k].total() + settings.body_force[k];
  drho_dt = summation ? 0.0 : rho_a * sum_rho.total() + diffusion * sum_delta.total();
}

/// 1/h of the first n particles (owned, then ghosts), in a buffer kept from step to step.
inline const double* inverse_smoothing_lengths(const double* h, std::size_t n) {
  thread_local std::vector<double> buffer;
  buffer.resize(n);
  double* inverse = buffer.data();
  flecsi_lite::forall(
    n, [=](std::size_t i) { inverse[i] = 1.0 / h[i]; }, "fluid::inverse_smoothing_lengths");
  return inverse;
}
}  // namespace detail

/// Accelerations and drho/dt of the owned fluid particles (walls get zero), and the smallest
/// time step of them: min(courant h / (c + |v|), acceleration_factor sqrt(h / |a|),
/// viscous_factor h^2 / nu) (Monaghan 1992; Morris et al. 1997 eqs. 23-25); the largest double
/// when there is no fluid particle.
template<int D>
double compute_fluid_rates(sph::neighbours_ro<D> neighbours_object, physics::kernel_type kernel_type,
                           fluid_settings settings, double courant, double acceleration_factor,
                           sph::ro_with_ghosts<vector<D>> x, sph::ro_with_ghosts<vector<D>> v,
                           sph::ro_with_ghosts<vector<D>> wall_velocity, sph::ro_with_ghosts<double> m,
                           sph::ro_with_ghosts<double> h, sph::ro_with_ghosts<double> rho,
                           sph::ro_with_ghosts<double> P, sph::ro_with_ghosts<double> cs,
                           sph::ro_with_ghosts<sph::particle_kind> kind, sph::wo<vector<D>> acceleration,
                           sph::wo<double> density_rate) {
  const sph::neighbourhood<D>& neighbours = *neighbours_object;
  const sph::neighbour_walk<D> walk(neighbours);
  const detail::rate_fields<D> in{x.data(),   v.data(), wall_velocity.data(),
                                  m.data(),   h.data(), detail::inverse_smoothing_lengths(h.data(), h.size()),
                                  rho.data(), P.data(), cs.data(),
                                  kind.data()};
  const bool summation = settings.density == density_method::summation;
  const double nu = settings.kinematic_viscosity();
  double smallest = std::numeric_limits<double>::max();
  physics::dispatch_kernel<D>(kernel_type, [&](auto kernel_type_tag) {
    using Kernel = decltype(kernel_type_tag);
    flecsi_lite::forall_reduce(
      neighbours.size(),
      [&](std::size_t a, double& local_smallest) {
        if (kind(a) != sph::particle_kind::fluid) {
          acceleration(a) = vector<D>{};
          density_rate(a) = 0;
          return;
        }
        vector<D> dv_dt;
        double drho_dt;
        detail::fluid_rates<Kernel, D>(walk, a, in, settings, summation, dv_dt, drho_dt);
        acceleration(a) = dv_dt;
        density_rate(a) = drho_dt;
        double a2 = 0, v2 = 0;
        for (int k = 0; k < D; ++k) a2 += dv_dt[k] * dv_dt[k], v2 += v(a)[k] * v(a)[k];
        const double h_a = h(a);
        double dt = courant * h_a / (cs(a) + std::sqrt(v2));
        if (a2 > 0) dt = std::min(dt, acceleration_factor * std::sqrt(h_a / std::sqrt(a2)));
        if (nu > 0) dt = std::min(dt, settings.viscous_factor * h_a * h_a / nu);
        local_smallest = std::min(local_smallest, dt);
      },
      Kokkos::Min<double>(smallest), "fluid::compute_fluid_rates", sph::target_schedule);
  });
  return smallest;
}

}  // namespace flecsph::fluid
