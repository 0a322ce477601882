// When to search the neighbours again (Verlet lists, Verlet 1967): the lists are searched
// list_skin beyond the reach the pair tasks need and kept over the steps until the particles'
// displacement and the growth of h since that search could have brought a pair within reach that
// the lists lack, the same test as the ghosts' (redistribution.hh). One reduction measures both.
#pragma once

#include "specialization/sph/model/neighbourhood.hh"
#include "specialization/sph/model/tasks.hh"
#include "specialization/sph/step/redistribution.hh"

#include <algorithm>
#include <cmath>
#include <limits>

namespace flecsph::sph {

/// Over the owned particles: the largest displacement since the lists were searched relative to
/// h then, |x_a - listed_x_a| / listed_h_a (displacement), and the largest growth h_a / listed_h_a.
struct list_slack {
  double displacement = 0;
  double growth = 0;
};

/// The lists were searched with reach R (1 + skin) max(h0_a, h0_b) at the positions x0; the pair
/// tasks need every pair within R max(h_a, h_b) now. With |x_a - x0_a| <= d h0_a and h_a <= g h0_a
/// for every particle (d, g: maxima over all ranks), such a pair had
/// |r0_ab| <= |r_ab| + (d h0_a + d h0_b) < (R g + 2 d) max(h0_a, h0_b), so the lists still hold it while
///   2 d + R g <= R (1 + skin)
/// (less 1e-12 of it for the rounding of the distances; d, g relative to h then). Its b is here
/// (ghosts_still_suffice, tested at the same steps), and was when the lists were searched: the
/// ghosts change only with a distribution, which searches again.
inline bool lists_still_suffice(const list_slack& slack, double support, double skin) {
  return 2 * slack.displacement + support * slack.growth <= support * (1 + skin) * (1 - 1e-12);
}

/// Both slacks of the step: the ghosts' since the distribution and the lists' since their search.
struct neighbour_slack {
  distribution_slack distribution;
  list_slack lists;
};

/// Reduction operation: the maximum of each member (exact, so every rank count decides alike).
struct neighbour_slack_reduction {
  static neighbour_slack combine(const neighbour_slack& a, const neighbour_slack& b) {
    return {slack_reduction::combine(a.distribution, b.distribution),
            {std::max(a.lists.displacement, b.lists.displacement), std::max(a.lists.growth, b.lists.growth)}};
  }
};

/// The task. A particle that crossed a periodic boundary (moved more than half a period along a
/// periodic axis) counts as infinitely displaced: its lists' image shifts are stale.
template<int D>
neighbour_slack measure_neighbour_slack(neighbours_ro<D> neighbours_object, tree::domain<D> space, ro<vector<D>> x,
                                        ro<double> h, ro<double> drift, ro<double> distributed_h) {
  const neighbourhood<D>& n = *neighbours_object;
  neighbour_slack slack;
  slack.distribution = measure_distribution_slack(h, drift, distributed_h);
  constexpr double infinite = std::numeric_limits<double>::infinity();
  if (n.listed_h.size() != h.size()) {  // no lists of these particles yet, or none to keep (no skin)
    slack.lists.displacement = infinite;
    return slack;
  }
  const auto displacement = [&](std::size_t a) {
    double d2 = 0;
    bool wrapped = false;
    for (int k = 0; k < D; ++k) {
      const double dx = x(a)[k] - n.listed_x[a][k];
      wrapped = wrapped || (space.periodic[k] && 2 * std::fabs(dx) > space.period(k));
      d2 += dx * dx;
    }
    return wrapped ? infinite : std::sqrt(d2) / n.listed_h[a];
  };
  slack.lists.displacement = flecsi_lite::forall_max(h.size(), displacement, slack.lists.displacement,
                                                     "sph::measure_neighbour_slack::displacement");
  slack.lists.growth = flecsi_lite::forall_max(
    h.size(), [&](std::size_t a) { return h(a) / n.listed_h[a]; }, slack.lists.growth,
    "sph::measure_neighbour_slack::growth");
  return slack;
}

}  // namespace flecsph::sph
