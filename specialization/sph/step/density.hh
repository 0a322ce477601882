// The density task: rho_a = sum_b m_b W(r_ab, h_a) (seed eq. 1.3), at fixed h or with the adaptive
// h = eta (m/rho)^(1/D) solved per particle by Newton-Raphson, and the grad-h factor Omega
// (Springel & Hernquist 2002; Price 2012, JCP 231, 759, sec. 3); with self-gravity also the
// grad-h gravity factor zeta (Price & Monaghan 2007, MNRAS 374, 1347); where they are read, the
// velocity divergence and curl at the final h (velocity_gradients.hh).
#pragma once

#include "specialization/physics/kernels/kernel_at.hh"
#include "specialization/sph/model/neighbourhood.hh"
#include "specialization/sph/model/settings.hh"
#include "specialization/sph/model/tasks.hh"
#include "specialization/sph/step/velocity_gradients.hh"

#include "specialization/physics/gravity_softening.hh"
#include "specialization/physics/kernels.hh"
#include "specialization/physics/pressure_energy.hh"
#include "specialization/physics/smoothing_length.hh"

#include "flecsi_lite/execution.hh"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace flecsph::sph {

namespace detail {
/// The density sums' packs: at most 4 lanes. With AVX-512's 8 the task took 1.8x the time of 4
/// lanes on a Xeon (Sapphire Rapids) while the force sums gained from 8 (docs/performance.md).
using density_pack = physics::simd::pack_at_most<4>;

/// What the density sums need of a's list, gathered once for all the Newton iterations of h_a:
/// |r_ab| (one square root per entry, not one per entry and iteration) and m_b per entry in list
/// order, padded to whole packs with entries out of reach (r = inf, m = 0). One per thread,
/// reused from target to target.
struct gathered_pairs {
  std::vector<double> r, m;
  std::vector<double> mu;          ///< m_b u_b, gathered for pressure-energy only
  std::size_t count = 0;           ///< list entries (the padding excluded)
  gathered_velocities velocities;  ///< gathered for the velocity gradients only
};

template<int D>
void gather_pairs(const neighbour_row<D>& row, std::size_t a, const vector<D>* x, const double* m, gathered_pairs& out,
                  const double* u = nullptr, const vector<D>* v = nullptr) {
  const std::size_t count = row.size(), W = physics::simd::lanes<density_pack>;
  const std::size_t padded = (count + W - 1) / W * W;
  if (out.r.size() < padded) {
    out.r.resize(padded);
    out.m.resize(padded);
  }
  if (u && out.mu.size() < padded) out.mu.resize(padded);
  if (v) out.velocities.make_room(padded, D);
  // Pack by pack; past the end, lanes repeat the last entry and are overwritten by the padding.
  namespace simd = physics::simd;
  using T = density_pack;
  for (std::size_t i = 0; i < count; i += W) {
    std::size_t b[simd::lanes<T>];
    T r[D];
    const T r2 = row.separations(i, x[a], x, b, r);
    simd::store(simd::square_root(r2), out.r.data() + i);
    simd::store(simd::generate<T>([&](std::size_t l) { return m[b[l]]; }), out.m.data() + i);
    if (u) simd::store(simd::generate<T>([&](std::size_t l) { return m[b[l]] * u[b[l]]; }), out.mu.data() + i);
    if (v) gather_velocity_terms<D>(i, b, r, r2, v[a], v, out.velocities);
  }
  for (std::size_t i = count; i < padded; ++i) {
    out.r[i] = std::numeric_limits<double>::infinity();
    out.m[i] = 0.0;
    if (u) out.mu[i] = 0.0;
  }
  if (v) pad_velocity_terms(count, padded, D, out.velocities);
  out.count = count;
}

/// sum_b w_b W(r_ab, h) and its derivative sum_b w_b dW/dh over a's gathered list with the
/// weights w (one per entry, padded as r), T the number type of the pair arithmetic
/// (physics/simd.hh); the terms go to striped sums in list order, so the sums are bitwise those
/// of T = double on every instruction set.
template<class Kernel, class T = density_pack>
void kernel_sums(const gathered_pairs& pairs, const double* weights, double h, double& sum_w, double& dsum_dh) {
  namespace simd = physics::simd;
  constexpr std::size_t W = simd::lanes<T>;
  const kernel_at<Kernel> kernel(h);
  const double reach = physics::kernel_support * h;
  simd::striped_sum<T> sum, derivative;
  const T zero = 0.0;
  for (std::size_t j = 0; j < pairs.count; j += W) {
    const T r = simd::load<T>(pairs.r.data() + j), m_b = simd::load<T>(weights + j);
    const auto inside = !(r >= reach);  // outside the kernel (or padding): the term is zero
    T w, dw_dh;
    kernel.value_and_h_derivative(r, w, dw_dh);
    sum.add(simd::select(inside, m_b * w, zero));
    derivative.add(simd::select(inside, m_b * dw_dh, zero));
  }
  sum_w = sum.total();
  dsum_dh = derivative.total();
}

/// rho(h) = sum_b m_b W(r_ab, h) and its derivative sum_b m_b dW/dh over a's gathered list.
template<class Kernel, class T = density_pack>
void density_sums(const gathered_pairs& pairs, double h, double& rho, double& drho_dh) {
  kernel_sums<Kernel, T>(pairs, pairs.m.data(), h, rho, drho_dh);
}

/// Pressure-energy (Hopkins 2013, sec. 2.4): P_bar_a = (gamma-1) sum_b m_b u_b W(r_ab, h_a) at
/// a's final h and its grad-h term g_a (physics/pressure_energy.hh; 0 with a fixed h). The pairs
/// must hold m_b u_b (gather_pairs with u).
template<class Kernel, int D>
void smoothed_pressure(const gathered_pairs& pairs, double gamma_minus_one, double h, double rho, double omega,
                       bool adapt, double& P_bar, double& grad_h) {
  double sum = 0, dsum_dh = 0;
  kernel_sums<Kernel>(pairs, pairs.mu.data(), h, sum, dsum_dh);
  P_bar = gamma_minus_one * sum;
  grad_h = adapt ? physics::pressure_energy_grad_h<D>(h, gamma_minus_one * dsum_dh, rho, omega) : 0.0;
}

/// zeta_a / Omega_a with zeta_a = (dh_a/drho_a) sum_b m_b d phi(r_ab, h_a) / d h_a (Price & Monaghan
/// 2007, sec. 3), dh/drho = -h / (3 rho) (0 for a fixed h): the self term b = a included.
template<class Kernel, int D>
double gravity_zeta_over_omega(const neighbour_row<D>& row, std::size_t a, double h, double rho, double omega,
                               bool adapt, const vector<D>* x, const double* m) {
  if constexpr (D != 3) {
    return 0.0;  // gravity is 3D only (check_gravity_domain)
  } else {
    if (!adapt) return 0.0;
    using softening = physics::softened_gravity<typename Kernel::shape>;
    const double reach2 = physics::kernel_support * physics::kernel_support * h * h;
    const vector<D>& x_a = x[a];
    double sum = 0;
    vector<D> r;
    for (std::size_t j = 0; j < row.size(); ++j) {
      const std::size_t b = row.neighbour(j);
      const double r2 = row.separation(x_a, x[b], j, r);
      if (r2 >= reach2) continue;
      sum += m[b] * softening::h_derivative(std::sqrt(r2), h);
    }
    return -h / (D * rho) * sum / omega;
  }
}

/// What the density pass adds for pressure-energy: u of owned particles and ghosts, and where
/// P_bar and its grad-h term go (owned).
struct pressure_energy_outputs {
  const double* u = nullptr;
  double *P_bar = nullptr, *grad_h = nullptr;
};

/// Writes target t's gradient terms at a's final h from its gathered pairs (gradient_terms).
template<class Kernel, int D>
void write_target_gradient_terms(const gathered_pairs& pairs, double h_a, std::size_t t, gradient_terms& out) {
  const kernel_at<Kernel> kernel_a(h_a);
  const double reach2 = physics::kernel_support * physics::kernel_support * h_a * h_a;
  const gathered_velocities& g = pairs.velocities;
  if (g.with_curl)
    write_gradient_terms<Kernel, D, true, density_pack>(g, pairs.r.data(), pairs.m.data(), pairs.count, kernel_a,
                                                        reach2, t, out);
  else
    write_gradient_terms<Kernel, D, false, density_pack>(g, pairs.r.data(), pairs.m.data(), pairs.count, kernel_a,
                                                         reach2, t, out);
}

/// div v_a = -1/(Omega_a rho_a) sum_b ... and |curl v_a| (gradients.curl not null) of the block's
/// targets a = targets[t], t < count, from their terms.
template<int D>
void finish_velocity_gradients(gradient_terms& terms, const std::uint32_t* targets, std::size_t count,
                               const double* rho, const double* omega, const velocity_gradient_outputs<D>& gradients) {
  double div[gradient_block];
  vector<3> rotation[gradient_block];
  if (gradients.curl)
    sum_gradient_terms<D, true>(terms, div, rotation);
  else
    sum_gradient_terms<D, false>(terms, div, rotation);
  for (std::size_t t = 0; t < count; ++t) {
    const std::size_t a = targets[t];
    const double scale = -1.0 / (omega[a] * rho[a]);
    gradients.divergence[a] = scale * div[t];
    if (gradients.curl)
      gradients.curl[a] =
        std::fabs(scale) *
        std::sqrt(rotation[t][0] * rotation[t][0] + rotation[t][1] * rotation[t][1] + rotation[t][2] * rotation[t][2]);
  }
}

/// The loop of compute_density; `zeta_over_omega` is null without gravity, `gradients` without
/// velocity gradients, `pressure` without pressure-energy.
template<int D, flecsi_lite::privilege Ghost>
double density_loop(const neighbourhood<D>& neighbours, const physics_settings& settings, double earlier,
                    const vector<D>* xs, const double* ms, ro<particle_kind> kind, rw<double> h, wo<double> rho,
                    wo<double> omega, double* zeta_over_omega, velocity_gradient_outputs<D> gradients,
                    pressure_energy_outputs pressure = {}) {
  const double gamma_minus_one = settings.eos.ideal.gamma - 1.0;
  const neighbour_walk<D> walk(neighbours);
  const std::vector<std::uint32_t>& targets = neighbours.targets(Ghost);
  const double half_reach = 0.5 * neighbours.reach;
  double worst = 0;
  physics::dispatch_kernel<D>(settings.kernel, [&](auto kernel) {
    using Kernel = decltype(kernel);
    // Blocks of targets, so that their gradient sums run side by side (gradient_terms).
    constexpr std::size_t B = gradient_block;
    flecsi_lite::forall_reduce(
      (targets.size() + B - 1) / B,
      [&](std::size_t block, double& local_worst) {
        const std::size_t first = block * B, count = std::min(B, targets.size() - first);
        thread_local gathered_pairs pairs;
        thread_local gradient_terms terms;
        const vector<D>* v = gradients.divergence ? gradients.v : nullptr;
        pairs.velocities.with_curl = gradients.curl != nullptr;
        terms.start_block();
        for (std::size_t t = 0; t < count; ++t) {
          const std::size_t a = targets[first + t];
          const double h_start = h(a), h_limit = half_reach * h_start;
          const bool adapt = settings.adaptive_smoothing_length && kind(a) == particle_kind::fluid;
          double h_a = h_start, rho_a = 0, drho_dh = 0;
          const neighbour_row<D> row = walk.row(a);
          gather_pairs<D>(row, a, xs, ms, pairs, pressure.u, v);
          for (int iteration = 1;; ++iteration) {
            density_sums<Kernel>(pairs, h_a, rho_a, drho_dh);
            if (!adapt || iteration >= settings.h_iterations) break;
            const double residual = physics::smoothing_length_residual<D>(h_a, rho_a, ms[a], settings.eta);
            if (std::fabs(residual) < settings.h_tolerance) break;
            h_a = physics::smoothing_length_newton_step<D>(h_a, rho_a, drho_dh, ms[a], settings.eta);
            if (h_a > h_limit) break;  // the list may miss neighbours: search again
          }
          h(a) = h_a;
          rho(a) = rho_a;
          omega(a) = adapt ? physics::grad_h_omega<D>(h_a, rho_a, drho_dh) : 1.0;
          // At h_a > h_limit the caller searches again and calls the task again: zeta is recomputed.
          if (zeta_over_omega)
            zeta_over_omega[a] = gravity_zeta_over_omega<Kernel, D>(row, a, h_a, rho_a, omega(a), adapt, xs, ms);
          if (pressure.u)
            smoothed_pressure<Kernel, D>(pairs, gamma_minus_one, h_a, rho_a, omega(a), adapt, pressure.P_bar[a],
                                         pressure.grad_h[a]);
          if (v) write_target_gradient_terms<Kernel, D>(pairs, h_a, t, terms);
          local_worst = std::max(local_worst, h_a / h_limit);
        }
        if (v) finish_velocity_gradients<D>(terms, targets.data() + first, count, rho.data(), omega.data(), gradients);
      },
      Kokkos::Max<double>(worst), "sph::compute_density", flecsi_lite::dynamic_schedule{target_schedule.chunk / B});
  });
  return std::max({worst, earlier, 0.0});  // no target: the reduction's identity is -inf
}
}  // namespace detail

/// Density (and, with adaptive h, the smoothing length and Omega) of the owned targets of one
/// part (neighbourhood::targets): launched once with Ghost = na for the interior targets, which
/// needs no ghost value, and once with Ghost = ro for the boundary ones. Of a neighbour b the sums
/// read x_b and m_b only (and v_b for the gradients); h, kind and the outputs are the target's
/// own. With `divergence` present, also div v (and |curl v| with `curl` present: the Balsara
/// switch) at the final h; v, divergence and curl are absent fields where nobody reads them.
/// Wall particles keep their h. Returns the largest of `earlier` (the value of the other part's launch) and h_a / h_limit_a
/// over this part's targets, where h_limit_a = reach/2 * (h_a at entry) is the largest h for
/// which a's list is complete: above 1, h grew out of the searched reach (h is then the grown
/// value, rho is not final) and the caller must search again and call this task again.
template<int D, flecsi_lite::privilege Ghost>
double compute_density(neighbours_ro<D> neighbours, physics_settings settings, double earlier,
                       ro_neighbours<vector<D>, Ghost> x, ro_neighbours<double, Ghost> m, ro<particle_kind> kind,
                       rw<double> h, wo<double> rho, wo<double> omega, ro_neighbours<vector<D>, Ghost> v,
                       wo<double> divergence, wo<double> curl) {
  return detail::density_loop<D, Ghost>(*neighbours, settings, earlier, x.data(), m.data(), kind, h, rho, omega,
                                        nullptr, {v.data(), divergence.data(), curl.data()});
}

/// The same with self-gravity: also zeta_a / Omega_a for the force pass (detail::gravity_zeta_over_omega).
template<int D, flecsi_lite::privilege Ghost>
double compute_density_with_gravity(neighbours_ro<D> neighbours, physics_settings settings, double earlier,
                                    ro_neighbours<vector<D>, Ghost> x, ro_neighbours<double, Ghost> m,
                                    ro<particle_kind> kind, rw<double> h, wo<double> rho, wo<double> omega,
                                    ro_neighbours<vector<D>, Ghost> v, wo<double> divergence, wo<double> curl,
                                    wo<double> zeta_over_omega) {
  return detail::density_loop<D, Ghost>(*neighbours, settings, earlier, x.data(), m.data(), kind, h, rho, omega,
                                        zeta_over_omega.data(), {v.data(), divergence.data(), curl.data()});
}

/// The same for pressure-energy (settings.pressure_energy()): also P_bar_a and its grad-h term
/// (detail::smoothed_pressure), which read the neighbours' u as well.
template<int D, flecsi_lite::privilege Ghost>
double compute_density_pressure_energy(neighbours_ro<D> neighbours, physics_settings settings, double earlier,
                                       ro_neighbours<vector<D>, Ghost> x, ro_neighbours<double, Ghost> m,
                                       ro<particle_kind> kind, rw<double> h, wo<double> rho, wo<double> omega,
                                       ro_neighbours<vector<D>, Ghost> v, wo<double> divergence, wo<double> curl,
                                       ro_neighbours<double, Ghost> u, wo<double> P_bar, wo<double> grad_h) {
  return detail::density_loop<D, Ghost>(*neighbours, settings, earlier, x.data(), m.data(), kind, h, rho, omega,
                                        nullptr, {v.data(), divergence.data(), curl.data()},
                                        {u.data(), P_bar.data(), grad_h.data()});
}

}  // namespace flecsph::sph
