// The velocity divergence and curl of the SPH particles (Price 2012, JCP 231, 759, eqs. 100-101):
// div v_a = -1/(Omega_a rho_a) sum_b m_b v_ab . grad_a W_ab(h_a) and |curl v_a| (the cross product
// form; zero in 1D). The Balsara (1995) switch reads both; individual time steps drift the
// inactive particles' rho and h with div v (time_bins.hh).
//
// The pair terms are computed on packs (numerics/simd.hh: every lane the scalar operations in the
// scalar order) and then added one by one in list order, as the plain loop over the list adds
// them (numerics/ordered_sum.hh): the sums are bitwise those of that loop, so moving the task onto
// packs changed no output. The plain loop spent 17% of an individual-step Sedov run (30^3, AMD
// Zen 2, perf) on one square root and one kernel derivative per pair; docs/performance.md.
#pragma once

#include "specialization/physics/kernels/kernel_at.hh"
#include "specialization/sph/model/neighbourhood.hh"
#include "specialization/sph/model/settings.hh"
#include "specialization/sph/model/tasks.hh"

#include "specialization/numerics/simd.hh"
#include "specialization/physics/kernels.hh"

#include "flecsi_lite/execution.hh"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <type_traits>

namespace flecsph::sph {

namespace detail {
/// The packs of the gradient sums: the adds are one lane at a time, so wider packs gain little.
using gradient_pack = physics::simd::pack_at_most<4>;

/// sum_b m_b v_ab . r_ab F_ab (into `div`) and, with WithCurl, sum_b m_b (v_ab x r_ab) F_ab (into
/// `rotation`) over a's list, F_ab = (1/r) dW/dr at h_a, for the entries with 0 < |r_ab|^2 < reach2;
/// T the number type of the pair arithmetic (double: the plain loop). A skipped entry adds +0 or
/// -0, which leaves a sum that started at +0 as skipping it does.
template<class Kernel, int D, bool WithCurl, class T = gradient_pack>
void velocity_gradient_sums(const neighbour_walk<D>& walk, std::size_t a, const vector<D>* x, const vector<D>* v,
                            const double* m, const kernel_at<Kernel>& kernel_a, double reach2, double& div,
                            vector<3>& rotation) {
  namespace simd = physics::simd;
  constexpr std::size_t W = simd::lanes<T>;
  const T zero = 0.0;
  const neighbour_row<D> row = walk.row(a);
  const std::size_t end = row.size();
  for (std::size_t j = 0; j < end; j += W) {
    std::size_t b[W];
    T r[D];
    const T r2 = row.separations(j, x[a], x, b, r);
    const auto inside = (r2 < reach2) && (r2 != 0.0);
    const T factor = simd::generate<T>([&](std::size_t l) { return m[b[l]]; }) *
                     kernel_a.gradient_factor(simd::square_root(r2));  // grad W = r factor
    // The plain loop's vector<3> of dv and r, zero beyond D.
    T dv[3] = {zero, zero, zero}, rr[3] = {zero, zero, zero}, div_terms[D];
    for (int k = 0; k < D; ++k) {
      dv[k] = v[a][k] - simd::generate<T>([&](std::size_t l) { return v[b[l]][k]; });
      rr[k] = r[k];
      div_terms[k] = simd::select(inside, dv[k] * r[k] * factor, zero);
    }
    T rotation_terms[3];
    if constexpr (WithCurl) {
      rotation_terms[0] = simd::select(inside, (dv[1] * rr[2] - dv[2] * rr[1]) * factor, zero);
      rotation_terms[1] = simd::select(inside, (dv[2] * rr[0] - dv[0] * rr[2]) * factor, zero);
      rotation_terms[2] = simd::select(inside, (dv[0] * rr[1] - dv[1] * rr[0]) * factor, zero);
    }
    // In list order; the lanes past the list's end (repeats of its last entry) are left out.
    const std::size_t lanes = std::min(W, end - j);
    for (std::size_t l = 0; l < lanes; ++l) {
      for (int k = 0; k < D; ++k) div += simd::element(div_terms[k], l);
      if constexpr (WithCurl)
        for (int k = 0; k < 3; ++k) rotation[k] += simd::element(rotation_terms[k], l);
    }
  }
}
}  // namespace detail

/// div v and, when `curl` is present (the Balsara switch), |curl v| of the owned targets of one
/// part (neighbourhood::targets): the interior ones with Ghost = na, the boundary ones with
/// Ghost = ro.
template<int D, flecsi_lite::privilege Ghost>
void compute_velocity_gradients(neighbours_ro<D> neighbours_object, physics_settings settings,
                                ro_neighbours<vector<D>, Ghost> x, ro_neighbours<vector<D>, Ghost> v,
                                ro_neighbours<double, Ghost> m, ro<double> h, ro<double> rho, ro<double> omega,
                                wo<double> divergence, wo<double> curl) {
  const neighbourhood<D>& neighbours = *neighbours_object;
  const neighbour_walk<D> walk(neighbours);
  const std::vector<std::uint32_t>& targets = neighbours.targets(Ghost);
  const vector<D>*xs = x.data(), *vs = v.data();
  const double* ms = m.data();
  const auto loop = [&](auto kernel, auto with_curl) {
    using Kernel = decltype(kernel);
    constexpr bool WithCurl = decltype(with_curl)::value;
    flecsi_lite::forall(
      targets.size(),
      [&](std::size_t i) {
        const std::size_t a = targets[i];
        const double h_a = h(a);
        const kernel_at<Kernel> kernel_a(h_a);  // 1/h and the normalisation once per target
        const double reach2 = physics::kernel_support * physics::kernel_support * h_a * h_a;
        double div = 0;
        vector<3> rotation{};
        detail::velocity_gradient_sums<Kernel, D, WithCurl>(walk, a, xs, vs, ms, kernel_a, reach2, div, rotation);
        const double scale = -1.0 / (omega(a) * rho(a));
        divergence(a) = scale * div;
        if constexpr (WithCurl)
          curl(a) = std::fabs(scale) *
                    std::sqrt(rotation[0] * rotation[0] + rotation[1] * rotation[1] + rotation[2] * rotation[2]);
      },
      "sph::compute_velocity_gradients");
  };
  // absent without the Balsara switch: div v only
  physics::dispatch_kernel<D>(settings.kernel, [&](auto kernel) {
    if (curl.data() != nullptr)
      loop(kernel, std::true_type{});
    else
      loop(kernel, std::false_type{});
  });
}

}  // namespace flecsph::sph
