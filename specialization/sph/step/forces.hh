// The force task: acceleration (seed eq. 1.9) and du/dt (eq. 1.8) in the pairwise-antisymmetric
// grad-h form (Price 2012, JCP 231, 759, eqs. 30-35), Monaghan & Gingold (1983) viscosity with the
// optional Balsara switch, Price (2008) artificial conductivity, and each particle's time step;
// with self-gravity the grad-h gravity term (Price & Monaghan 2007, MNRAS 374, 1347, sec. 3) and
// the tree's acceleration, so that the time step sees the total acceleration.
#pragma once

#include "specialization/physics/kernels/kernel_at.hh"
#include "specialization/sph/model/tasks.hh"
#include "specialization/sph/step/density.hh"
#include "specialization/sph/step/equation_of_state.hh"

#include "specialization/physics/time_step.hh"
#include "specialization/physics/viscosity.hh"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <type_traits>
#include <vector>

namespace flecsph::sph {

namespace detail {
/// The fields the force loop reads, as raw arrays over owned and ghost particles.
template<int D>
struct force_fields {
  const vector<D>* x;
  const vector<D>* v;
  const double *m, *h, *rho, *P, *cs, *pressure_term, *u;
  /// The per-particle factor of Pi_ab: the Balsara factor, or alpha of the Cullen & Dehnen switch
  /// (viscosity_factor); null with both off: every factor is 1, and Pi_ab * 1 = Pi_ab.
  const double* balsara;
  // Self-gravity only: zeta / Omega (owned and ghosts), G a of the tree (owned) and G / 2.
  const double* zeta_over_omega = nullptr;
  const vector<D>* gravity_acceleration = nullptr;
  double half_G = 0;
  /// 1/h of every particle the lists name (inverse_smoothing_lengths): once per particle, not
  /// once per pair.
  const double* inverse_h = nullptr;
  // Pressure-energy only (formulation = pressure_energy): the grad-h term g of P_bar (owned and
  // ghosts) and gamma - 1; pressure_term then holds A = (gamma-1) u / P_bar.
  const double* pressure_grad_h = nullptr;
  double gamma_minus_one = 0;
};

/// 1/h of the first n particles (owned, then ghosts), computed once per launch of the force task.
inline void inverse_smoothing_lengths(const double* h, std::size_t n, std::vector<double>& out) {
  out.resize(n);
  double* inverse = out.data();
  flecsi_lite::forall(
    n, [=](std::size_t i) { inverse[i] = 1.0 / h[i]; }, "sph::compute_forces::inverse_h");
}

/// The buffer of inverse_smoothing_lengths, one per launching thread, shared by the interior and
/// the boundary launches of every dimension: kept from step to step, no allocation per launch.
inline std::vector<double>& inverse_h_buffer() {
  thread_local std::vector<double> buffer;
  return buffer;
}

/// The sums of compute_forces for particle a: dv/dt, du/dt and the largest signal velocity.
/// Conductivity is a compile-time choice: without it, the loop has less to keep live. With
/// GradHGravity the bracket of dv/dt has the grad-h gravity term (G/2)(z_a F_a + z_b F_b),
/// z = zeta / Omega, as symmetric in (a, b) as the pressure term. With PressureEnergy the
/// pressure part of the bracket is A_a (q_b - g_a) F_a + A_b (q_a - g_b) F_b, q = (gamma-1) u
/// (physics/pressure_energy.hh), and du/dt takes its first term.
///
/// T is the number type of the pair arithmetic: a pack (physics/simd.hh) takes lanes() list
/// entries at once, gathered from the fields; entries beyond the kernel, beyond the list or at
/// r = 0 are lanes whose terms are zeroed. The terms go to striped sums (simd::striped_sum) in
/// list order, so the sums are bitwise those of T = double (tests/specialization/sph/simd_pairs.cc)
/// on every instruction set. A pair costs one square root and two divisions (1/r and the
/// viscosity's): 1/h comes per particle, and 1/q = h/r.
template<class Kernel, bool Conductivity, bool GradHGravity, bool PressureEnergy, int D, class T = physics::simd::pack>
void force_sums(const neighbour_walk<D>& walk, std::size_t a, const force_fields<D>& in,
                const physics::viscosity_parameters& viscosity, double conductivity, vector<D>& dv_dt, double& du,
                double& signal) {
  namespace simd = physics::simd;
  constexpr std::size_t W = simd::lanes<T>;
  const double support2 = physics::kernel_support * physics::kernel_support;
  const vector<D> x_a = in.x[a], v_a = in.v[a];
  const double h_a = in.h[a], rho_a = in.rho[a], c_a = in.cs[a], term_a = in.pressure_term[a];
  const kernel_at<Kernel, T> kernel_a(T(h_a), T(in.inverse_h[a]));
  const physics::basic_viscosity_particle<T> particle_a{rho_a, c_a, h_a, in.balsara ? in.balsara[a] : 1.0};
  const T lane = simd::generate<T>([](std::size_t i) { return double(i); });
  simd::striped_sum<T> sum_v[D], sum_u;
  T largest = c_a;
  const neighbour_row<D> row = walk.row(a);
  const std::size_t end = row.size();
  for (std::size_t j0 = 0; j0 < end; j0 += W) {
    // Lane i holds entry j0 + i; past the end it repeats the last entry, masked out below.
    std::size_t b[W];
    T r[D], r_dot_v = 0.0;
    const T r2 = row.separations(j0, x_a, in.x, b, r);
    const auto gather = [&](const double* field) {
      return simd::generate<T>([&](std::size_t i) { return field[b[i]]; });
    };
    const T h_b = gather(in.h), h_max = simd::maximum(T(h_a), h_b);
    const auto pair = (lane < double(end - j0)) && !(r2 >= support2 * h_max * h_max) && (r2 != 0.0);
    const T zero = 0.0;
    if (!simd::any_lane(pair)) {
      for (int k = 0; k < D; ++k) sum_v[k].skip();
      sum_u.skip();
      continue;
    }
    const T distance = simd::square_root(r2), inverse_r = 1.0 / distance;
    const T F_a = kernel_a.gradient_factor(distance, inverse_r);
    const T F_b = kernel_at<Kernel, T>(h_b, gather(in.inverse_h)).gradient_factor(distance, inverse_r);
    const T F_ab = 0.5 * (F_a + F_b);
    for (int k = 0; k < D; ++k) {
      const T v_b = simd::generate<T>([&](std::size_t i) { return in.v[b[i]][k]; });
      r_dot_v += r[k] * (v_a[k] - v_b);
    }
    const T c_b = gather(in.cs), rho_b = gather(in.rho);
    // Viscosity acts on approaching pairs only (Pi_ab = 0 otherwise).
    const T Pi =
      simd::select(r_dot_v < 0.0,
                   physics::approaching_pair_viscosity<T>(viscosity, r_dot_v, r2, particle_a,
                                                          {rho_b, c_b, h_b, in.balsara ? gather(in.balsara) : T(1.0)}),
                   zero);
    // The pressure part of the bracket whose first term is a's own (du/dt takes it).
    T own_term, bracket;
    if constexpr (PressureEnergy) {
      const T q_b = in.gamma_minus_one * gather(in.u);
      own_term = term_a * (q_b - in.pressure_grad_h[a]) * F_a;
      const T other = gather(in.pressure_term) * (in.gamma_minus_one * in.u[a] - gather(in.pressure_grad_h)) * F_b;
      bracket = (own_term + other) + Pi * F_ab;
    } else {
      own_term = term_a * F_a;
      bracket = (own_term + gather(in.pressure_term) * F_b) + Pi * F_ab;
    }
    if constexpr (GradHGravity) bracket += in.half_G * (in.zeta_over_omega[a] * F_a + gather(in.zeta_over_omega) * F_b);
    const T m_b = gather(in.m);
    for (int k = 0; k < D; ++k) sum_v[k].subtract(simd::select(pair, m_b * bracket * r[k], zero));
    T work = m_b * (own_term + 0.5 * Pi * F_ab) * r_dot_v;
    if constexpr (Conductivity)
      work += m_b * physics::artificial_conductivity<T>(conductivity, in.u[a], gather(in.u), in.P[a], gather(in.P),
                                                        rho_a, rho_b, F_ab * distance);
    sum_u.add(simd::select(pair, work, zero));
    largest = simd::maximum(
      largest, simd::select(pair, physics::signal_velocity_from_inverse<T>(c_a, c_b, r_dot_v, inverse_r), zero));
  }
  for (int k = 0; k < D; ++k) dv_dt[k] = sum_v[k].total();
  du = sum_u.total();
  signal = simd::largest_lane(largest);
}
}  // namespace detail

/// The per-particle factor of Pi_ab (force_fields::balsara) and, through `settings`, the viscosity
/// parameters: with the Cullen & Dehnen switch alpha_a itself, the parameters' alpha 1 and beta
/// beta / alpha, so that Pi_ab = alpha_ab [beta / alpha mu^2 - c mu] / rho with alpha_ab the mean
/// of the pair (beta = 2 alpha_ab by default, as CD10 sec. 2.1); else the Balsara factors or none.
inline const double* viscosity_factor(physics_settings& settings, const double* balsara, const double* alpha) {
  if (settings.viscosity_switch.enabled) {
    settings.viscosity.beta /= settings.viscosity.alpha;
    settings.viscosity.alpha = 1.0;
    return alpha;
  }
  return settings.balsara ? balsara : nullptr;
}

namespace detail {
/// The loop of compute_forces over one part's targets, whose lists name the first `particles`
/// particles; with `in.gravity_acceleration` set (self-gravity) the tree's acceleration is added,
/// and the grad-h gravity term with in.zeta_over_omega.
template<int D, flecsi_lite::privilege Ghost>
double force_loop(const neighbourhood<D>& neighbours, const physics_settings& settings, double earlier,
                  force_fields<D> in, std::size_t particles, ro<particle_kind> kind, wo<vector<D>> acceleration,
                  wo<double> du_dt, wo<double> own_time_step) {
  const neighbour_walk<D> walk(neighbours);
  const std::vector<std::uint32_t>& targets = neighbours.targets(Ghost);
  std::vector<double>& inverse_h = inverse_h_buffer();
  inverse_smoothing_lengths(in.h, particles, inverse_h);
  in.inverse_h = inverse_h.data();
  double smallest = std::numeric_limits<double>::max();
  const auto loop = [&](auto kernel_type, auto with_conductivity, auto grad_h_gravity, auto pressure_energy) {
    using Kernel = decltype(kernel_type);
    flecsi_lite::forall_reduce(
      targets.size(),
      [&](std::size_t i, double& local_smallest) {
        const std::size_t a = targets[i];
        vector<D> dv_dt;
        double du, signal;
        force_sums<Kernel, decltype(with_conductivity)::value, decltype(grad_h_gravity)::value,
                   decltype(pressure_energy)::value, D>(walk, a, in, settings.viscosity, settings.conductivity, dv_dt,
                                                        du, signal);
        if (in.gravity_acceleration)
          for (int k = 0; k < D; ++k) dv_dt[k] += in.gravity_acceleration[a][k];
        acceleration(a) = dv_dt;
        du_dt(a) = du;
        if (kind(a) != particle_kind::fluid) {
          own_time_step(a) = std::numeric_limits<double>::infinity();
          return;
        }
        double a2 = 0;
        for (int k = 0; k < D; ++k) a2 += dv_dt[k] * dv_dt[k];
        const double h_a = in.h[a];
        double dt = physics::courant_time_step(settings.courant, h_a, signal);
        if (a2 > 0) dt = std::min(dt, settings.acceleration_factor * std::sqrt(h_a / std::sqrt(a2)));
        own_time_step(a) = dt;
        local_smallest = std::min(local_smallest, dt);
      },
      Kokkos::Min<double>(smallest), "sph::compute_forces", target_schedule);
  };
  physics::dispatch_kernel<D>(settings.kernel, [&](auto kernel_type) {
    const auto with_gravity_term = [&](auto with_conductivity) {
      if (in.zeta_over_omega)
        loop(kernel_type, with_conductivity, std::true_type{}, std::false_type{});
      else if (in.pressure_grad_h)
        loop(kernel_type, with_conductivity, std::false_type{}, std::true_type{});
      else
        loop(kernel_type, with_conductivity, std::false_type{}, std::false_type{});
    };
    if (settings.conductivity > 0)
      with_gravity_term(std::true_type{});
    else
      with_gravity_term(std::false_type{});
  });
  return std::min(smallest, earlier);
}
}  // namespace detail

/// Accelerations and du/dt of the owned targets of one part (neighbourhood::targets): launched
/// with Ghost = na for the interior targets, which needs no ghost value, and with Ghost = ro for
/// the boundary ones. Returns the smallest of `earlier` (the other part's value) and the time
/// steps of this part's fluid particles (the largest double when there is none):
/// min(courant h_a / max_b v_sig,ab, acceleration_factor sqrt(h_a / |a_a|)).
///
/// For a pair (a, b) with r_ab = x_a - x_b, F_x = (1/r) dW/dr(r, h_x), F_ab = (F_a + F_b)/2 and the
/// pressure terms p_x = P_x / (Omega_x rho_x^2) (field pressure_term):
///   dv_a/dt = -sum_b m_b [p_a F_a + p_b F_b + Pi_ab F_ab] r_ab
///   du_a/dt =  sum_b m_b [p_a F_a + Pi_ab F_ab / 2] v_ab . r_ab
///            + sum_b m_b alpha_u v_sig^u (u_a - u_b) / rho_ab F_ab |r_ab|
/// The bracket of dv/dt is computed by the same symmetric expression for (a, b) and (b, a), so the
/// pair forces are exactly opposite: momentum is conserved to round-off, energy to the accuracy of
/// the time integration. Pressure-energy (field pressure_grad_h, present with formulation =
/// pressure_energy) replaces p_a F_a by A_a (q_b - g_a) F_a and p_b F_b by A_b (q_a - g_b) F_b
/// (detail::force_sums; P is then P_bar). P is read only with the conductivity, u only with it or
/// pressure-energy: otherwise they may be absent (update_forces does not pass them).
template<int D, flecsi_lite::privilege Ghost>
double compute_forces(neighbours_ro<D> neighbours, physics_settings settings, double earlier,
                      ro_neighbours<vector<D>, Ghost> x, ro_neighbours<vector<D>, Ghost> v,
                      ro_neighbours<double, Ghost> m, ro_neighbours<double, Ghost> h, ro_neighbours<double, Ghost> rho,
                      ro_neighbours<double, Ghost> P, ro_neighbours<double, Ghost> cs,
                      ro_neighbours<double, Ghost> pressure_term, ro_neighbours<double, Ghost> u,
                      ro_neighbours<double, Ghost> balsara, ro_neighbours<double, Ghost> alpha,
                      ro_neighbours<double, Ghost> pressure_grad_h, ro<particle_kind> kind, wo<vector<D>> acceleration,
                      wo<double> du_dt, wo<double> own_time_step) {
  detail::force_fields<D> in{x.data(),   v.data(),
                             m.data(),   h.data(),
                             rho.data(), P.data(),
                             cs.data(),  pressure_term.data(),
                             u.data(),   viscosity_factor(settings, balsara.data(), alpha.data())};
  if (settings.pressure_energy()) {
    in.pressure_grad_h = pressure_grad_h.data();
    in.gamma_minus_one = settings.eos.ideal.gamma - 1.0;
  }
  return detail::force_loop<D, Ghost>(*neighbours, settings, earlier, in, h.size(), kind, acceleration, du_dt,
                                      own_time_step);
}

/// The same with self-gravity (Price & Monaghan 2007, sec. 3): dv_a/dt also has
///   -(G/2) sum_b m_b [z_a F_a + z_b F_b] r_ab,   z = zeta / Omega (field zeta_over_omega),
/// the grad-h gravity term (left out when settings.gravity.grad_h is off), and the tree's G a_a
/// (field gravity_acceleration, the pair part softened with phi of the kernel); the time step
/// sees the sum.
template<int D, flecsi_lite::privilege Ghost>
double compute_forces_with_gravity(neighbours_ro<D> neighbours, physics_settings settings, double earlier,
                                   ro_neighbours<vector<D>, Ghost> x, ro_neighbours<vector<D>, Ghost> v,
                                   ro_neighbours<double, Ghost> m, ro_neighbours<double, Ghost> h,
                                   ro_neighbours<double, Ghost> rho, ro_neighbours<double, Ghost> P,
                                   ro_neighbours<double, Ghost> cs, ro_neighbours<double, Ghost> pressure_term,
                                   ro_neighbours<double, Ghost> u, ro_neighbours<double, Ghost> balsara,
                                   ro_neighbours<double, Ghost> alpha, ro_neighbours<double, Ghost> zeta_over_omega,
                                   ro<vector<D>> gravity_acceleration, ro<particle_kind> kind,
                                   wo<vector<D>> acceleration, wo<double> du_dt, wo<double> own_time_step) {
  detail::force_fields<D> in{x.data(),   v.data(),
                             m.data(),   h.data(),
                             rho.data(), P.data(),
                             cs.data(),  pressure_term.data(),
                             u.data(),   viscosity_factor(settings, balsara.data(), alpha.data())};
  if (settings.gravity.grad_h) in.zeta_over_omega = zeta_over_omega.data();
  in.gravity_acceleration = gravity_acceleration.data();
  in.half_G = 0.5 * settings.gravity.constant;
  return detail::force_loop<D, Ghost>(*neighbours, settings, earlier, in, h.size(), kind, acceleration, du_dt,
                                      own_time_step);
}

}  // namespace flecsph::sph
