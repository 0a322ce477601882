// Barnes-Hut tree walk with an opening-angle criterion (Barnes & Hut 1986, Nature 324, 446):
// the nodes whose multipole expansion may stand for their particles, and the particles that
// must be summed directly, for a target point or a group of targets in a box.
#pragma once

#include "flecsi_lite/topology/ntree/detail/search_dispatch.hh"
#include "flecsi_lite/topology/ntree/space.hh"
#include "flecsi_lite/topology/ntree/tree/hashed_tree.hh"

#include <cassert>
#include <cstdint>
#include <vector>

namespace flecsi_lite::topology::ntree {

/// What a target interacts with: accepted nodes (use their moments) and particles (sum
/// directly), each in ascending key order. A target's own particle may be among `particles`.
struct interaction_list {
  std::vector<std::uint32_t> nodes;
  std::vector<std::uint32_t> particles;

  void clear() {
    nodes.clear();
    particles.clear();
  }
};

/// The opening criterion: a node may stand for its particles when the targets' box does not
/// meet its bounding box and size < theta * distance, where size is the largest side of the
/// node's bounding box and distance the shortest from the targets' box to its centre of mass.
/// With theta = 0 no node is accepted.
template<int D>
inline bool barnes_hut_accepts(const tree_node<D>& node, const box<D>& targets, double theta) {
  if (targets.intersects(node.bounds)) return false;
  const double size = node.bounds.max_extent();
  return size * size < theta * theta * distance_squared<D>(targets, node.centre);
}

/// Fills `out` with the interaction list of the targets in box `targets` (a point is a box
/// with lo = hi): accepted nodes are not opened, rejected leaves give their particles.
template<int D>
void barnes_hut_walk(const hashed_tree<D>& tree, const box<D>& targets, double theta, interaction_list& out) {
  assert(theta >= 0);
  out.clear();
  if (tree.size() == 0) return;
  std::uint32_t stack[walk_stack_size<D>];
  int top = 0;
  stack[top++] = 0;
  while (top > 0) {
    const std::uint32_t index = stack[--top];
    const tree_node<D>& node = tree.node(index);
    if (barnes_hut_accepts<D>(node, targets, theta)) {
      out.nodes.push_back(index);
    } else if (node.is_leaf()) {
      for (std::uint32_t b = node.begin; b < node.end; ++b) out.particles.push_back(b);
    } else {
      for (std::uint32_t c = node.first_child + node.child_count; c-- > node.first_child;) {
        assert(top < walk_stack_size<D>);
        stack[top++] = c;
      }
    }
  }
}

/// The interaction list of a single target point.
template<int D>
void barnes_hut_walk(const hashed_tree<D>& tree, const point<D>& target, double theta, interaction_list& out) {
  barnes_hut_walk<D>(tree, box<D>{target, target}, theta, out);
}

}  // namespace flecsi_lite::topology::ntree
