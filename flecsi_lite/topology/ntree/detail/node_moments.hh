// Bottom-up quantities of one tree node (tight bounds, largest h, mass, centre of mass, traceless
// quadrupole; Barnes & Hut 1986, Hernquist 1987) from its particles or from its children in order.
#pragma once

#include "flecsi_lite/topology/ntree/space.hh"
#include "flecsi_lite/topology/ntree/tree/multipole.hh"

#include <algorithm>
#include <cstdint>

namespace flecsi_lite::topology::ntree::detail {

// The one place these sums are written: hashed_tree (every node) and the distributed gravity
// tree (the nodes that straddle ranks) both call it, so a node has the same bits whichever of
// them computed it, given the same particles or children in the same order. `Node` is
// tree_node<D> (templated to keep this header below hashed_tree.hh).

/// A leaf from its particles: x, m, h indexed by node.begin .. node.end. `q`: nullptr when the
/// quadrupoles are not wanted.
template<int D, class Node>
void compute_leaf_moments(Node& node, const point<D>* x, const double* m, const double* h, quadrupole<D>* q) {
  node.bounds = box<D>::empty();
  node.h_max = 0;
  node.mass = 0;
  point<D> weighted{};
  for (std::uint32_t b = node.begin; b < node.end; ++b) {
    node.bounds.extend(x[b]);
    node.h_max = std::max(node.h_max, h[b]);
    node.mass += m[b];
    for (int k = 0; k < D; ++k) weighted[k] += m[b] * x[b][k];
  }
  if (node.mass > 0) {
    for (int k = 0; k < D; ++k) node.centre[k] = weighted[k] / node.mass;
  } else {
    node.centre = node.size() > 0 ? node.bounds.centre() : point<D>{};
  }
  if (q == nullptr) return;
  // The moments about the centre of mass: offsets of the particles, viewed as Eigen vectors.
  q->setZero();
  const auto centre = as_column_vector<D>(node.centre);
  for (std::uint32_t b = node.begin; b < node.end; ++b) add_point_mass<D>(*q, m[b], as_column_vector<D>(x[b]) - centre);
}

/// An inner node from its children nodes[node.first_child ..], in that order; `quadrupoles`
/// (per node, same indices) and `q` are both nullptr when the quadrupoles are not wanted.
template<int D, class Node>
void compute_parent_moments(Node& node, const Node* nodes, const quadrupole<D>* quadrupoles, quadrupole<D>* q) {
  node.bounds = box<D>::empty();
  node.h_max = 0;
  node.mass = 0;
  point<D> weighted{};
  const std::uint32_t last = node.first_child + node.child_count;
  for (std::uint32_t c = node.first_child; c < last; ++c) {
    const Node& child_node = nodes[c];
    node.bounds.extend(child_node.bounds);
    node.h_max = std::max(node.h_max, child_node.h_max);
    node.mass += child_node.mass;
    for (int k = 0; k < D; ++k) weighted[k] += child_node.mass * child_node.centre[k];
  }
  if (node.mass > 0) {
    for (int k = 0; k < D; ++k) node.centre[k] = weighted[k] / node.mass;
  } else {
    node.centre = node.size() > 0 ? node.bounds.centre() : point<D>{};
  }
  if (q == nullptr) return;
  // Parallel-axis shift of the children's moments to this node's centre of mass.
  q->setZero();
  const auto centre = as_column_vector<D>(node.centre);
  for (std::uint32_t c = node.first_child; c < last; ++c)
    add_shifted<D>(*q, quadrupoles[c], nodes[c].mass, as_column_vector<D>(nodes[c].centre) - centre);
}

}  // namespace flecsi_lite::topology::ntree::detail
