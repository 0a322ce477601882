// When to distribute the particles again (seed Algorithm 3, line 5, skipped while it is safe, as
// DESIGN suggests): ghosts are chosen with a skin beyond the search reach (a Verlet skin,
// Verlet 1967), and the local tree is only refitted until the particles' motion and the growth of
// their smoothing lengths could have brought a missing particle within reach.
#pragma once

#include "specialization/sph/model/neighbourhood.hh"
#include "specialization/sph/model/tasks.hh"

#include <algorithm>

namespace flecsph::sph {

/// The largest path length since the last distribution, relative to h then (drift), and the
/// largest growth h / h_then (growth), over the owned particles.
struct distribution_slack {
  double drift = 0;
  double growth = 0;
};

/// Reduction operation: the maximum of each member.
struct slack_reduction {
  static distribution_slack combine(distribution_slack a, const distribution_slack& b) {
    return {std::max(a.drift, b.drift), std::max(a.growth, b.growth)};
  }
};

/// Ghosts were selected within reach R_g = support (1 + skin) max(h_a, h_b) of the positions at
/// the last distribution; the search now needs every pair within support max(h_a, h_b) of the
/// current positions. A pair's distance changed by at most drift_a + drift_b (path lengths) and
/// each h grew by at most `growth`, so the ghosts still suffice while
///   2 drift + support growth <= support (1 + skin)   (drift, growth relative to h then).
inline bool ghosts_still_suffice(const distribution_slack& slack, double support, double skin) {
  return 2 * slack.drift + support * slack.growth <= support * (1 + skin);
}

/// Over the owned particles, in parallel (maxima from 0, as the serial loop had them; 1.1 s of one
/// thread in a 38 s run, Sedov 3D 100^3 at 1 x 2, when it was that loop).
inline distribution_slack measure_distribution_slack(ro<double> h, ro<double> drift, ro<double> distributed_h) {
  return {flecsi_lite::forall_max(
            h.size(), [&](std::size_t a) { return drift(a) / distributed_h(a); }, 0.0,
            "sph::measure_distribution_slack::drift"),
          flecsi_lite::forall_max(
            h.size(), [&](std::size_t a) { return h(a) / distributed_h(a); }, 0.0,
            "sph::measure_distribution_slack::growth")};
}

/// balance = work: each owned particle weighs its list length at the last search in the next
/// distribution (its pair sums cost in proportion; seed section 2.3.3).
template<int D>
void measure_work(neighbours_ro<D> neighbours, wo<double> work) {
  const auto& lists = neighbours->lists;
  flecsi_lite::forall(
    work.size(), [&](std::size_t a) { work(a) = a < lists.size() ? static_cast<double>(lists.count(a)) : 0.0; },
    "sph::measure_work");
}

/// After a distribution: the path lengths start again from zero, from the current h and position
/// (the keys of this distribution follow from that position, for restarts).
template<int D>
void mark_distributed(ro<double> h, ro<vector<D>> x, wo<double> drift, wo<double> distributed_h,
                      wo<vector<D>> distributed_x) {
  flecsi_lite::forall(
    h.size(),
    [&](std::size_t a) {
      drift(a) = 0;
      distributed_h(a) = h(a);
      distributed_x(a) = x(a);
    },
    "sph::mark_distributed");
}

}  // namespace flecsph::sph
