// Self-gravity by a tree walk (Barnes & Hut 1986; groups of targets as Barnes 1990): monopole +
// quadrupole moments of the accepted nodes (Hernquist 1987), a caller-supplied softened near
// field for the particles of the opened leaves, and GADGET-2's relative opening criterion
// (Springel 2005). G = 1: the caller scales. The summation order is fixed (see gravity_walk).
#pragma once

#include "flecsi_lite/execution/forall.hh"
#include "flecsi_lite/topology/ntree/gravity/detail/gravity_interactions.hh"
#include "flecsi_lite/topology/ntree/space.hh"
#include "flecsi_lite/topology/ntree/tree/hashed_tree.hh"
#include "flecsi_lite/topology/ntree/tree/multipole.hh"

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace flecsi_lite::topology::ntree {

struct gravity_options {
  /// Geometric Barnes-Hut opening angle: a node stands for its particles when l < theta (d -
  /// delta): l its largest side, d the distance from the group's box to its centre of mass,
  /// delta that centre's offset from the centre of its bounds (Barnes 1994); 0 opens all.
  double theta = 0.5;
  /// GADGET-2's relative criterion (Springel 2005, eq. 18): M l^2 / r^4 <= alpha |a_old|, with
  /// its guard (the group's box outside the node's cube widened by 0.1 side per face). Where a
  /// group's old accelerations are unknown (acceleration_min = 0) theta decides instead.
  bool relative_criterion = false;
  double relative_tolerance = 0.0025;  ///< its alpha
  /// A node whose bounds come within near_factor * max(node h_max, group h_max) of the group's
  /// box is always opened, so a softened pair is never replaced by a multipole.
  double near_factor = 2;
  bool quadrupole = true;        ///< use the nodes' quadrupoles (else monopoles only)
  std::size_t bucket_size = 16;  ///< leaf size of the gravity tree (for whoever builds it)
  std::size_t group_size = 32;   ///< targets walked together
};

/// A tree of source particles, read only: nodes[0] is the root, children contiguous as in
/// hashed_tree; the particle arrays are indexed by tree_node::begin/end.
template<int D>
struct gravity_sources {
  const tree_node<D>* nodes = nullptr;
  std::size_t node_count = 0;
  const quadrupole<D>* quadrupoles = nullptr;  ///< per node; nullptr: monopole only
  const point<D>* x = nullptr;
  const double* m = nullptr;
  const double* h = nullptr;  ///< nullptr: all zero
};

/// The sources view of a hashed tree (its quadrupoles when it computed them).
template<int D>
gravity_sources<D> gravity_sources_of(const hashed_tree<D>& tree) {
  gravity_sources<D> sources;
  sources.nodes = tree.nodes().data();
  sources.node_count = tree.nodes().size();
  sources.quadrupoles = tree.has_quadrupoles() ? &tree.node_quadrupole(0) : nullptr;
  sources.x = tree.positions();
  sources.m = tree.masses();
  sources.h = tree.smoothing_lengths();
  return sources;
}

/// Targets walked with one interaction list. bounds, h_max and acceleration_min describe ALL
/// the particles of the group's node (also those another rank owns), begin/end the targets of
/// this caller in it (indices into the target arrays).
template<int D>
struct target_group {
  box<D> bounds = box<D>::empty();
  double h_max = 0;
  double acceleration_min = 0;  ///< smallest |a_old| (relative criterion only; 0: unknown)
  std::uint32_t begin = 0, end = 0;
};

/// The groups of a tree: node N is a group when (N.size() <= group_size or N is a leaf) and (N
/// is the root or its parent's size() > group_size), in node order, so they partition the
/// particles. acceleration_old (|a| per particle in tree order, nullable) fills
/// acceleration_min. Target indices are the tree's particle order.
template<int D>
std::vector<target_group<D>> target_groups(const hashed_tree<D>& tree, std::size_t group_size,
                                           const double* acceleration_old = nullptr) {
  std::vector<target_group<D>> groups;
  if (tree.size() == 0) return groups;
  const auto& nodes = tree.nodes();
  const auto is_group = [&](const tree_node<D>& node) { return node.size() <= group_size || node.is_leaf(); };
  const auto add = [&](const tree_node<D>& node) {
    target_group<D> group;
    group.bounds = node.bounds;
    group.h_max = node.h_max;
    group.begin = node.begin;
    group.end = node.end;
    if (acceleration_old) {
      group.acceleration_min = acceleration_old[node.begin];
      for (std::uint32_t i = node.begin + 1; i < node.end; ++i)
        group.acceleration_min = std::min(group.acceleration_min, acceleration_old[i]);
    }
    groups.push_back(group);
  };
  if (is_group(nodes[0])) {
    add(nodes[0]);
    return groups;
  }
  // Children of nodes in index order come in index order (first_child grows with the index).
  for (const tree_node<D>& node : nodes) {
    if (node.is_leaf() || node.size() <= group_size) continue;
    for (std::uint32_t c = node.first_child; c < node.first_child + node.child_count; ++c)
      if (is_group(nodes[c])) add(nodes[c]);
  }
  return groups;
}

/// Where the field is wanted: positions and softening lengths (nullptr: all zero). `wanted`
/// (nullable: every target) marks the targets whose field is asked for: a group with none of them
/// is not walked and its targets' results are left as they were; the others' are those of the
/// whole walk, to the bit (a group's sums depend on its own targets and the tree only). With
/// individual time steps this walks only the groups of the active particles.
template<int D>
struct gravity_targets {
  const point<D>* x = nullptr;
  const double* h = nullptr;
  const std::uint8_t* wanted = nullptr;
};

/// What the near-field function returns for a pair at distance r: source j adds
/// m_j * potential to the target's potential and -m_j * radial * (x_i - x_j) to its
/// acceleration. Newtonian: {-1/r, 1/r^3}.
struct softened_pair {
  double potential;
  double radial;
};

/// Interactions summed, over all targets (a cost diagnostic).
struct gravity_counts {
  std::uint64_t node_interactions = 0;
  std::uint64_t particle_interactions = 0;
};

/// Accelerations and potentials (G = 1) of every target of `groups` (of the groups holding a
/// wanted target, when targets.wanted is given).
///
/// near(r, h_target, h_source) -> softened_pair must equal the Newtonian pair beyond
/// near_factor * max(h_target, h_source) and give radial = 0 at r = 0 (a target meets itself in
/// its leaf; its potential gets the self term); for momentum conservation it must be symmetric
/// in the two h.
///
/// The order of summation is part of the contract: for every group, one interaction list
/// (depth-first from the root, children in node order; an accepted node is kept, an opened leaf
/// gives its particles); then for each target of the group the accepted nodes in visit order
/// (multipole_field's arithmetic), then the particles in visit order through `near` (or, beyond
/// near_factor * max(h) with a margin, the Newtonian pair it equals there), each term added to
/// running sums that start at zero. Targets are summed in blocks, one lane each (vectorised
/// across targets, never within one target's sum), so a target's result is that of its own
/// sequential sum. The result thus
/// depends only on the visited nodes' data (bounds, centre, mass, h_max, quadrupole, children)
/// and the particles' (x, m, h) in leaf order, not on threads or on where the tree came from.
/// Groups run in parallel (dynamic schedule), each thread with its own interaction list.
/// acceleration and potential (nullable) are indexed like the targets.
template<int D, class Near>
gravity_counts gravity_walk(const gravity_sources<D>& sources, const std::vector<target_group<D>>& groups,
                            const gravity_targets<D>& targets, const gravity_options& options, const Near& near,
                            point<D>* acceleration, double* potential) {
  std::atomic<std::uint64_t> node_interactions{0}, particle_interactions{0};
  const quadrupole<D>* quadrupoles = options.quadrupole ? sources.quadrupoles : nullptr;
  flecsi_lite::forall(
    groups.size(),
    [&](std::size_t g) {
      // One list and one block per thread, kept between walks: no allocation once warm.
      thread_local detail::gravity_list<D> list;
      thread_local detail::target_block<D> block;
      const target_group<D>& group = groups[g];
      if (targets.wanted && std::none_of(targets.wanted + group.begin, targets.wanted + group.end,
                                         [](std::uint8_t wanted) { return wanted != 0; }))
        return;
      detail::build_gravity_list<D>(sources, group, options, quadrupoles, list);
      constexpr std::uint32_t width = detail::target_block<D>::width;
      for (std::uint32_t first = group.begin; first < group.end; first += width) {
        block.count = std::min(width, group.end - first);
        for (std::uint32_t t = 0; t < block.count; ++t) {
          for (int k = 0; k < D; ++k) block.x[k][t] = targets.x[first + t][k];
          block.h[t] = targets.h ? targets.h[first + t] : 0.0;
        }
        detail::sum_gravity_list<D>(list, options.near_factor, near, block);
        for (std::uint32_t t = 0; t < block.count; ++t) {
          if (acceleration)
            for (int k = 0; k < D; ++k) acceleration[first + t][k] = block.a[k][t];
          if (potential) potential[first + t] = block.phi[t];
        }
      }
      const std::uint64_t count = group.end - group.begin;
      node_interactions.fetch_add(count * list.nodes.size(), std::memory_order_relaxed);
      particle_interactions.fetch_add(count * list.particles(), std::memory_order_relaxed);
    },
    "ntree::gravity_walk", flecsi_lite::dynamic_schedule{});
  return {node_interactions.load(), particle_interactions.load()};
}

}  // namespace flecsi_lite::topology::ntree
