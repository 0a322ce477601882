// Opening criteria of the gravity walk for a group of targets in a box: the geometric
// Barnes-Hut test with the centre-of-mass offset (Barnes & Hut 1986; Barnes 1994), the near-field
// rule that keeps softened pairs exact, and GADGET-2's relative criterion with its guard
// (Springel 2005, MNRAS 364, 1105, eq. 18 and sec. 3.1).
#pragma once

#include "flecsi_lite/topology/ntree/space.hh"
#include "flecsi_lite/topology/ntree/tree/hashed_tree.hh"

#include <algorithm>
#include <cmath>

namespace flecsi_lite::topology::ntree::detail {

/// The near-field rule: true when some point of the node's bounds comes within
/// near_factor * max(node h_max, group h_max) of the group's box, so that a softened pair might
/// lie in it (the box distance never exceeds a pair's distance: the rule is exact).
template<int D>
inline bool within_softening(const tree_node<D>& node, const box<D>& group, double group_h_max, double near_factor) {
  const double reach = near_factor * std::max(node.h_max, group_h_max);
  return distance_squared<D>(node.bounds, group) <= reach * reach;
}

/// GADGET-2's guard: the group's box meets the node's cube (side = largest side of the bounds,
/// centred on them) widened by 0.1 side on each face, i.e. |x - centre| < 0.6 side on every
/// axis for some target x: a mass distribution that is lopsided in its cell could then put
/// the target close to much of its mass, which the relative estimate does not see.
template<int D>
inline bool inside_widened_cube(const tree_node<D>& node, const box<D>& group) {
  const point<D> centre = node.bounds.centre();
  const double half = 0.6 * node.bounds.max_extent();
  for (int k = 0; k < D; ++k)
    if (group.hi[k] <= centre[k] - half || group.lo[k] >= centre[k] + half) return false;
  return true;
}

/// GADGET-2 eq. 18 with G = 1: the node may stand for its particles when
/// M l^2 / r^4 <= alpha |a_old| for every target, r being the shortest distance from the group's
/// box to the node's centre of mass and |a_old| the group's smallest old acceleration.
template<int D>
inline bool relative_accepts(const tree_node<D>& node, const box<D>& group, double acceleration_min, double alpha) {
  if (group.intersects(node.bounds) || inside_widened_cube<D>(node, group)) return false;
  const double side = node.bounds.max_extent();
  const double r2 = distance_squared<D>(group, node.centre);
  return r2 > 0 && node.mass * side * side <= alpha * acceleration_min * r2 * r2;
}

/// The geometric test: l < theta (d - delta), i.e. d > l / theta + delta (Barnes 1994), l the
/// largest side of the node's bounds, d the shortest distance from the group's box to the
/// node's centre of mass, delta the offset of that centre from the centre of the bounds. The
/// offset (barnes_hut_accepts has none) opens the nodes whose mass sits on the side facing the
/// targets, where the plain test errs most (Salmon & Warren 1994); theta = 0 accepts nothing.
template<int D>
inline bool geometric_accepts(const tree_node<D>& node, const box<D>& group, double theta) {
  if (group.intersects(node.bounds)) return false;
  const double offset = std::sqrt(distance_squared<D>(node.bounds.centre(), node.centre));
  const double reach = node.bounds.max_extent() + theta * offset;
  return reach * reach < theta * theta * distance_squared<D>(group, node.centre);
}

/// The whole test for one node and one group; Group and Options are target_group<D> and
/// gravity_options of gravity.hh. The relative criterion replaces the geometric one where the
/// group's old accelerations are known (acceleration_min > 0), as in GADGET-2 after its first
/// step; elsewhere (and without it) the geometric test decides.
template<int D, class Group, class Options>
inline bool gravity_accepts(const tree_node<D>& node, const Group& group, const Options& options) {
  if (within_softening<D>(node, group.bounds, group.h_max, options.near_factor)) return false;
  if (options.relative_criterion && group.acceleration_min > 0)
    return relative_accepts<D>(node, group.bounds, group.acceleration_min, options.relative_tolerance);
  return geometric_accepts<D>(node, group.bounds, options.theta);
}

}  // namespace flecsi_lite::topology::ntree::detail
