// The velocity divergence and curl of the SPH particles (Price 2012, JCP 231, 759, eqs. 100-101):
// div v_a = -1/(Omega_a rho_a) sum_b m_b v_ab . grad_a W_ab(h_a) and |curl v_a| (the cross product
// form; zero in 1D). The Balsara (1995) switch reads both; individual time steps drift the
// inactive particles' rho and h with div v (time_bins.hh).
//
// They are summed in the density pass (density.hh), once a's h is final: that pass has already
// decoded a's list and gathered |r_ab| and m_b, so the sums cost no second walk of the list, no
// second square root and no second gather of the positions (a task of their own took as long as
// the density; docs/performance.md). Their pair terms are computed on packs
// (numerics/simd.hh: every lane the scalar operations in the scalar order) and added one by one
// in list order, as the plain loop over the list adds them: the sums are bitwise that loop's. Such
// a sum is one chain of dependent adds, so the density pass runs the chains of 8 targets side by
// side (sum_gradient_terms).
#pragma once

#include "specialization/physics/kernels/kernel_at.hh"
#include "specialization/sph/model/neighbourhood.hh"

#include "specialization/numerics/simd.hh"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <iterator>
#include <limits>
#include <vector>

namespace flecsph::sph::detail {

/// What the gradient sums need of a's list beside |r_ab| and m_b, gathered per entry with them
/// (padded as they are, to whole packs): |r_ab|^2, for the plain loop's reach test to the bit,
/// the products (v_a - v_b)_k r_ab,k (k < D) and, with the curl, (v_ab x r_ab)_k. The kernel
/// factor depends on the final h_a and multiplies them in the sums.
struct gathered_velocities {
  std::vector<double> r2;
  std::vector<double> dv_r[3], cross[3];
  bool with_curl = false;

  void make_room(std::size_t padded, int dimension) {
    if (r2.size() >= padded) return;
    r2.resize(padded);
    for (int k = 0; k < dimension; ++k) dv_r[k].resize(padded);
    for (auto& c : cross) c.resize(padded);
  }
};

/// Stores the terms of the entries i .. i + lanes<T> (neighbours b, separations r and r2 as the
/// density pass gathered them).
template<int D, class T, std::size_t Lanes>
FLECSPH_SIMD_INLINE void gather_velocity_terms(std::size_t i, const std::size_t (&b)[Lanes], const T (&r)[D],
                                               const T& r2, const vector<D>& v_a, const vector<D>* v,
                                               gathered_velocities& out) {
  namespace simd = physics::simd;
  const T zero = 0.0;
  // The plain loop's vector<3> of dv and r, zero beyond D.
  T dv[3] = {zero, zero, zero}, rr[3] = {zero, zero, zero};
  for (int k = 0; k < D; ++k) {
    dv[k] = v_a[k] - simd::generate<T>([&](std::size_t l) { return v[b[l]][k]; });
    rr[k] = r[k];
    simd::store(T(dv[k] * r[k]), out.dv_r[k].data() + i);
  }
  simd::store(r2, out.r2.data() + i);
  if (out.with_curl) {
    simd::store(T(dv[1] * rr[2] - dv[2] * rr[1]), out.cross[0].data() + i);
    simd::store(T(dv[2] * rr[0] - dv[0] * rr[2]), out.cross[1].data() + i);
    simd::store(T(dv[0] * rr[1] - dv[1] * rr[0]), out.cross[2].data() + i);
  }
}

/// Pads the entries count .. padded as out of reach.
inline void pad_velocity_terms(std::size_t count, std::size_t padded, int dimension, gathered_velocities& out) {
  for (std::size_t i = count; i < padded; ++i) {
    out.r2[i] = std::numeric_limits<double>::infinity();
    for (int k = 0; k < dimension; ++k) out.dv_r[k][i] = 0.0;
    if (out.with_curl)
      for (auto& c : out.cross) c[i] = 0.0;
  }
}

/// Targets whose sums are added side by side. Each target's sum is one chain of dependent adds in
/// list order (the order that fixes its bits): alone, a target waits one add latency per term, D
/// per entry; the chains of 8 targets, one a lane of a pack, keep the adder busy.
inline constexpr std::size_t gradient_block = 8;

/// The terms of a block's targets, term i of target t at i * gradient_block + t: D per entry for
/// div v, 3 per entry for the rotation. One per thread, reused from block to block.
struct gradient_terms {
  std::vector<double> div, rotation;
  std::size_t length[gradient_block] = {};  ///< list entries of target t (0: no target)

  void start_block() { std::fill(std::begin(length), std::end(length), std::size_t(0)); }
};

/// Writes target t's terms of sum_b m_b v_ab . r_ab F_ab and, with WithCurl, of sum_b m_b
/// (v_ab x r_ab) F_ab over its `count` gathered entries (|r_ab| in r, m_b in m), F_ab = (1/r) dW/dr
/// at h_a, in the order the plain loop adds them; the entries with |r_ab|^2 = 0 or >= reach2 give
/// +0 (which leaves a sum that started at +0 as skipping them does). T the number type of the
/// pair arithmetic (double: the plain loop).
template<class Kernel, int D, bool WithCurl, class T>
void write_gradient_terms(const gathered_velocities& g, const double* r, const double* m, std::size_t count,
                          const kernel_at<Kernel>& kernel_a, double reach2, std::size_t t, gradient_terms& out) {
  namespace simd = physics::simd;
  constexpr std::size_t W = simd::lanes<T>, B = gradient_block;
  const auto make_room = [&](std::vector<double>& terms, std::size_t per_entry) {
    if (terms.size() < count * per_entry * B) terms.resize(count * per_entry * B + count * per_entry * B / 4);
  };
  make_room(out.div, D);
  if constexpr (WithCurl) make_room(out.rotation, 3);
  const T zero = 0.0;
  for (std::size_t j = 0; j < count; j += W) {
    const T r2 = simd::load<T>(g.r2.data() + j);
    const auto inside = (r2 < reach2) && (r2 != 0.0);
    const T factor = simd::load<T>(m + j) * kernel_a.gradient_factor(simd::load<T>(r + j));  // grad W = r factor
    T div_terms[D], rotation_terms[3];
    for (int k = 0; k < D; ++k) div_terms[k] = simd::select(inside, simd::load<T>(g.dv_r[k].data() + j) * factor, zero);
    if constexpr (WithCurl)
      for (int k = 0; k < 3; ++k)
        rotation_terms[k] = simd::select(inside, simd::load<T>(g.cross[k].data() + j) * factor, zero);
    // The padding lanes are left out.
    const std::size_t lanes = std::min(W, count - j);
    for (std::size_t l = 0; l < lanes; ++l) {
      for (int k = 0; k < D; ++k) out.div[((j + l) * D + k) * B + t] = simd::element(div_terms[k], l);
      if constexpr (WithCurl)
        for (int k = 0; k < 3; ++k) out.rotation[((j + l) * 3 + k) * B + t] = simd::element(rotation_terms[k], l);
    }
  }
  out.length[t] = count;
}

/// The sums of the block's targets t < gradient_block (those without terms give 0): each adds its
/// terms one by one in list order, the plain loop's order, so the bits are that loop's; the
/// chains run side by side in the lanes of a pack, the shorter ones padded with +0 (a sum that
/// starts at +0 is never -0, so adding +0 leaves it as it is).
template<int D, bool WithCurl>
void sum_gradient_terms(gradient_terms& terms, double (&div)[gradient_block], vector<3> (&rotation)[gradient_block]) {
  namespace simd = physics::simd;
  constexpr std::size_t B = gradient_block;
  using chains = simd::pack_at_most<B>;
  constexpr std::size_t W = simd::lanes<chains>;
  const std::size_t longest = *std::max_element(std::begin(terms.length), std::end(terms.length));
  if (terms.div.size() < longest * D * B) terms.div.resize(longest * D * B);  // targets without terms
  if (WithCurl && terms.rotation.size() < longest * 3 * B) terms.rotation.resize(longest * 3 * B);
  for (std::size_t t = 0; t < B; ++t) {
    for (std::size_t i = terms.length[t] * D; i < longest * D; ++i) terms.div[i * B + t] = 0.0;
    if constexpr (WithCurl)
      for (std::size_t i = terms.length[t] * 3; i < longest * 3; ++i) terms.rotation[i * B + t] = 0.0;
  }
  chains div_sum[B / W], rotation_sum[3][B / W];
  for (std::size_t g = 0; g < B / W; ++g) {
    div_sum[g] = 0.0;
    for (int k = 0; k < 3; ++k) rotation_sum[k][g] = 0.0;
  }
  for (std::size_t i = 0; i < longest * D; ++i)
    for (std::size_t g = 0; g < B / W; ++g) div_sum[g] += simd::load<chains>(terms.div.data() + i * B + g * W);
  if constexpr (WithCurl)
    for (std::size_t i = 0; i < longest; ++i)
      for (int k = 0; k < 3; ++k)
        for (std::size_t g = 0; g < B / W; ++g)
          rotation_sum[k][g] += simd::load<chains>(terms.rotation.data() + (i * 3 + k) * B + g * W);
  for (std::size_t t = 0; t < B; ++t) {
    div[t] = simd::element(div_sum[t / W], t % W);
    for (int k = 0; k < 3; ++k) rotation[t][k] = WithCurl ? simd::element(rotation_sum[k][t / W], t % W) : 0.0;
  }
}

/// Where the density pass writes the gradients (owned), and the velocities they read (owned and
/// ghosts); null `divergence`: no gradients, null `curl`: div v only.
template<int D>
struct velocity_gradient_outputs {
  const vector<D>* v = nullptr;
  double *divergence = nullptr, *curl = nullptr;
};

}  // namespace flecsph::sph::detail
