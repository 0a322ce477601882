// Reference self-gravity by direct summation over all pairs (O(N^2)), with the same softened
// near-field function as the tree walk: the definition gravity_walk approximates, for tests and
// benchmarks.
#pragma once

#include "flecsi_lite/execution/forall.hh"
#include "flecsi_lite/topology/ntree/gravity/detail/gravity_interactions.hh"
#include "flecsi_lite/topology/ntree/space.hh"

#include <cstddef>

namespace flecsi_lite::topology::ntree {

/// Accelerations and potentials (G = 1; either output nullable) at the `count` targets
/// `which[t]` (indices of the n particles) of all n particles, each target summing j = 0..n-1
/// in order through near(r, h_i, h_j) (itself included: its self term), in parallel over targets.
/// acceleration[t], potential[t] belong to target which[t]. h nullptr: all zero.
template<int D, class Near>
void direct_gravity(const point<D>* x, const double* m, const double* h, std::size_t n, const std::size_t* which,
                    std::size_t count, const Near& near, point<D>* acceleration, double* potential) {
  flecsi_lite::forall(
    count,
    [&](std::size_t t) {
      const std::size_t i = which ? which[t] : t;
      point<D> a{};
      double phi = 0;
      const double hi = h ? h[i] : 0.0;
      for (std::size_t j = 0; j < n; ++j) detail::add_pair<D>(x[i], hi, x[j], m[j], h ? h[j] : 0.0, near, a, phi);
      if (acceleration) acceleration[t] = a;
      if (potential) potential[t] = phi;
    },
    "ntree::direct_gravity", flecsi_lite::dynamic_schedule{});
}

/// The same for every particle as a target (acceleration[i], potential[i] of particle i).
template<int D, class Near>
void direct_gravity(const point<D>* x, const double* m, const double* h, std::size_t n, const Near& near,
                    point<D>* acceleration, double* potential) {
  direct_gravity<D>(x, m, h, n, nullptr, n, near, acceleration, potential);
}

}  // namespace flecsi_lite::topology::ntree
