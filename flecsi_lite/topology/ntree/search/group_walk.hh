// The two-step group walk of FleCSPH (Loiseau, thesis ch. 2, Algorithm 2; Barnes 1990): descend
// to groups of nearby particles, build one interaction list per group with a box-distance
// criterion, then apply the exact pair criterion to every target of the group with that list.
#pragma once

#include "flecsi_lite/execution/forall.hh"
#include "flecsi_lite/topology/ntree/detail/search_dispatch.hh"
#include "flecsi_lite/topology/ntree/periodic.hh"
#include "flecsi_lite/topology/ntree/search/detail/list_filter.hh"
#include "flecsi_lite/topology/ntree/search/detail/neighbour_list_builder.hh"
#include "flecsi_lite/topology/ntree/search/neighbour_lists.hh"
#include "flecsi_lite/topology/ntree/search/radius_search.hh"
#include "flecsi_lite/topology/ntree/tree/hashed_tree.hh"

#include <algorithm>
#include <array>
#include <cassert>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace flecsi_lite::topology::ntree {

/// A group is a node whose particles share one interaction list: the first node on the way
/// down that is a leaf, or that holds at most max_group_size particles or (when
/// max_group_mass > 0) weighs at most max_group_mass (the seed's tmass), and, when
/// max_group_extent > 0, whose box is no wider than max_group_extent times its largest
/// interaction radius (support * h_max): sparse nodes, whose list would be long, are split.
/// A group whose interaction list comes out longer than max_list_length falls back to one
/// tree walk per target (same result): near steep density gradients, the box of a few sparse
/// targets enlarged by their large reach can take in thousands of particles of the dense side.
struct group_options {
  std::size_t max_group_size = 32;
  double max_group_mass = 0;
  double max_group_extent = 0;
  std::size_t max_list_length = 2048;
};

/// The interaction list of a group is every source image (x_b + shift) that may lie within
/// reach of some target of the group: within support * max(h of targets) of the targets' box
/// (and, for symmetric searches, within support * h_b). It is built in ascending (b, shift)
/// order and stored as structure of arrays so the per-target loop streams through it.
///
/// A group_walk object keeps its workspaces between calls (no allocation once warm); one
/// object must not be used by two threads at once.
template<int D>
class group_walk {
 public:
  explicit group_walk(search_options search = {}, group_options groups = {}) : search_(search), grouping_(groups) {}

  const search_options& options() const { return search_; }
  const group_options& grouping() const { return grouping_; }

  /// Calls apply(a, b) or apply(a, b, shift) for every target a and each neighbour b, in
  /// parallel over groups: the calls for one target come from one thread, in ascending b.
  template<class F>
  void for_each_neighbour(const hashed_tree<D>& tree, const domain<D>& space, F&& apply) {
    check_functor<D, std::remove_reference_t<F>>(space);
    const auto shifts = space.shift_table();
    run(
      tree, space, [](std::size_t) {},
      [&](std::size_t, workspace& work, auto kind, auto periodic) {
        walk_group<decltype(kind)::value, decltype(periodic)::value>(
          tree, shifts, space.allowed_shifts(), work,
          [&](std::size_t a, std::size_t count, const auto& neighbour, const auto& shift) {
            for (std::size_t i = 0; i < count; ++i) call_apply<D>(apply, a, neighbour(i), shift(i), shifts);
          });
      });
  }

  /// Neighbour lists of all targets, written as `layout` says (by default: one row per
  /// particle, tree indices, separate shift codes when the domain is periodic).
  void find_neighbours(const hashed_tree<D>& tree, const domain<D>& space, neighbour_lists& out,
                       const list_layout& layout = {});

  /// Searches for lists that walked twice (their lists outgrew the room of the previous ones).
  std::size_t repeated_list_passes() const { return builder_.repeated_passes(); }

  /// The groups (node indices, in ascending particle order) of the last walk.
  const std::vector<std::uint32_t>& groups() const { return groups_; }

  /// Memory held between walks: the groups and the per-thread workspaces.
  std::size_t bytes() const {
    std::size_t total = (groups_.capacity() + group_stack_.capacity() + walked_.capacity() + group_bounds_.capacity()) *
                        sizeof(std::uint32_t);
    for (const workspace& work : workspaces_) total += work.bytes();
    return total;
  }

  /// Total length of the interaction lists of the last walk (a cost diagnostic).
  std::size_t interaction_list_entries() const {
    std::size_t total = 0;
    for (const workspace& work : workspaces_) total += work.entries;
    return total;
  }

 private:
  // The interaction list lives in the first `length` entries of the arrays, which only grow
  // (geometrically), so that entries can be written before knowing whether they are kept.
  struct workspace {
    std::size_t group = 0;    // index in groups_ being walked
    std::size_t entries = 0;  // interaction-list entries built by this workspace
    std::size_t length = 0;   // entries of the current list
    std::vector<std::uint32_t> index;
    std::vector<shift_code> shift;
    std::array<std::vector<double>, D> position;
    std::vector<double> reach_squared;  // (support h_b)^2 of each source (symmetric searches)
    std::vector<std::uint32_t> hits;    // per-target scratch: list entries that are neighbours

    std::size_t bytes() const {
      return index.capacity() *
             (sizeof(std::uint32_t) + sizeof(shift_code) + (D + 1) * sizeof(double) + sizeof(std::uint32_t));
    }

    void reserve(std::size_t size) {
      if (index.size() >= size) return;
      const std::size_t grown = std::max(size, 2 * index.size());
      index.resize(grown);
      shift.resize(grown);
      for (auto& axis : position) axis.resize(grown);
      reach_squared.resize(grown);
      hits.resize(grown);
    }
  };

  // Finds the groups, then calls body(chunk, workspace, kind, periodic) for every group, in
  // parallel over chunks of consecutive groups. `prepare(chunks)` runs first, once.
  template<class Prepare, class Body>
  void run(const hashed_tree<D>& tree, const domain<D>& space, Prepare&& prepare, Body&& body) {
    check_periodic_reach(tree, space, search_.support);
    // Groups chosen by size alone depend on the nodes' ranges only, which a refit keeps: found
    // once per build (a serial descent of the whole tree, 1-2% of an individual-step run).
    const bool by_size_only = grouping_.max_group_mass <= 0 && grouping_.max_group_extent <= 0;
    if (!by_size_only || groups_build_ != tree.build_id()) {
      find_groups(tree);
      groups_build_ = by_size_only ? tree.build_id() : 0;
    }
    // With chosen targets only the groups holding one are walked (individual time steps: a
    // few percent of the particles are targets, and most groups hold none).
    const bool chosen = search_.targets != nullptr;
    if (chosen) find_groups_with_targets();
    const std::size_t group_count = chosen ? walked_.size() : groups_.size();
    const std::size_t chunks = chunk_count_for(group_count);
    if (workspaces_.size() < chunks) workspaces_.resize(chunks);
    for (workspace& work : workspaces_) work.entries = 0;
    prepare(chunks);
    if (group_count == 0) return;
    dispatch_search(search_.kind, space.any_periodic(), [&](auto kind, auto periodic) {
      flecsi_lite::forall(
        chunks,
        [&](std::size_t c) {
          workspace& work = workspaces_[c];
          for (std::size_t g = group_count * c / chunks; g < group_count * (c + 1) / chunks; ++g) {
            work.group = chosen ? walked_[g] : g;
            body(c, work, kind, periodic);
          }
        },
        "ntree::group_walk", flecsi_lite::dynamic_schedule{});
    });
  }

  // Step 1 (FIND_NODES): the groups, by a depth-first descent in key order.
  void find_groups(const hashed_tree<D>& tree);
  // walked_: the indices in groups_ of the groups that hold a target (search_.targets).
  void find_groups_with_targets();

  // Steps 2 and 3 (INTERACTION_LIST, APPLY_SUB_TREE) for the group work.group: calls
  // emit(a, count, neighbour, shift) once for every target a of the group, whose neighbours
  // are neighbour(i) under shift code shift(i), i < count, in ascending neighbour order.
  template<interaction Kind, bool Periodic, class Emit>
  void walk_group(const hashed_tree<D>& tree, const std::array<point<D>, shift_code_count<D>>& shifts,
                  std::uint32_t allowed, workspace& work, Emit&& emit) const {
    const tree_node<D>& group = tree.node(groups_[work.group]);
    const point<D>* positions = tree.positions();
    const double* h = tree.smoothing_lengths();
    const double support = search_.support;

    // The targets' own box and largest h bound every target's reach.
    box<D> targets = box<D>::empty();
    double h_targets = 0;
    for (std::uint32_t a = group.begin; a < group.end; ++a) {
      if (!search_.is_target(a)) continue;
      targets.extend(positions[a]);
      h_targets = std::max(h_targets, h[a]);
    }
    if (targets.is_empty()) return;
    build_list<Kind, Periodic>(tree, shifts, allowed, targets, support * h_targets, work);
    if (work.length > grouping_.max_list_length) {
      for (std::uint32_t a = group.begin; a < group.end; ++a) {
        if (!search_.is_target(a)) continue;
        walk_target<D, Kind, Periodic>(tree, shifts, allowed, positions[a], h[a], support,
                                       [&](std::size_t b, shift_code c) {
                                         emit(
                                           a, 1, [b](std::size_t) { return b; }, [c](std::size_t) { return c; });
                                       });
      }
      return;
    }

    const std::size_t length = work.length;
    const std::uint32_t* index = work.index.data();
    const shift_code* code = work.shift.data();
    std::uint32_t* hits = work.hits.data();
    std::array<const double*, D> source_x;
    for (int k = 0; k < D; ++k) source_x[k] = work.position[k].data();
    for (std::uint32_t a = group.begin; a < group.end; ++a) {
      if (!search_.is_target(a)) continue;
      // Symmetric: (support max(h_a, h_b))^2 = max((support h_a)^2, (support h_b)^2), rounding
      // being monotonic: the decision of within_radius and interaction_radius.
      const double radius = interaction_radius<Kind>(support, h[a], 0.0);
      const std::size_t count =
        within_reach<D>(positions[a], source_x, length, radius * radius,
                        Kind == interaction::symmetric ? work.reach_squared.data() : nullptr, hits);
      emit(
        a, count, [index, hits](std::size_t i) { return index[hits[i]]; },
        [code, hits](std::size_t i) { return Periodic ? code[hits[i]] : zero_shift<D>; });
    }
  }

  // The group's interaction list (INTERACTION_LIST): a node is opened while its box, seen
  // under some image shift, is within reach of the targets' box; leaves add their particles
  // that are themselves within reach of that box. Children are tested before being pushed.
  template<interaction Kind, bool Periodic>
  void build_list(const hashed_tree<D>& tree, const std::array<point<D>, shift_code_count<D>>& shifts,
                  std::uint32_t allowed, const box<D>& targets, double group_radius, workspace& work) const {
    const search_node<D>* nodes = tree.search_nodes().data();
    const point<D>* positions = tree.positions();
    const double* h = tree.smoothing_lengths();
    const double support = search_.support;

    const auto reachable = [&](const search_node<D>& node, std::uint32_t candidates) {
      return reachable_shifts<Kind, Periodic>(node, targets, group_radius, support, shifts, candidates);
    };

    std::size_t length = 0;
    const auto leaf = [&](const search_node<D>& node, std::uint32_t node_shifts) {
      const std::size_t images = Periodic ? __builtin_popcount(node_shifts) : 1;
      work.reserve(length + images * (node.end - node.begin));
      std::uint32_t* __restrict index = work.index.data();
      shift_code* __restrict code = work.shift.data();
      double* __restrict source_reach_squared = work.reach_squared.data();
      std::array<double*, D> source_x;
      for (int k = 0; k < D; ++k) source_x[k] = work.position[k].data();
      // Every candidate is written, and kept by advancing `length` only if within reach.
      const auto keep = [&](std::uint32_t b, shift_code c, const point<D>& image, double radius_b, bool within) {
        index[length] = b;
        code[length] = c;
        for (int k = 0; k < D; ++k) source_x[k][length] = image[k];
        source_reach_squared[length] = radius_b * radius_b;
        length += within;
      };
      for (std::uint32_t b = node.begin; b < node.end; ++b) {
        const double radius_b = support * h[b];
        const double reach_b = interaction_radius<Kind>(1.0, group_radius, radius_b);
        if constexpr (Periodic) {
          for (std::uint32_t rest = node_shifts; rest != 0; rest &= rest - 1) {
            const int c = __builtin_ctz(rest);
            point<D> image;
            for (int k = 0; k < D; ++k) image[k] = positions[b][k] + shifts[c][k];
            keep(b, static_cast<shift_code>(c), image, radius_b,
                 within_radius(distance_squared<D>(targets, image), reach_b));
          }
        } else {
          keep(b, zero_shift<D>, positions[b], radius_b,
               within_radius(distance_squared<D>(targets, positions[b]), reach_b));
        }
      }
    };
    walk_reachable_leaves<D>(nodes, Periodic ? allowed : 1u, reachable, leaf);
    work.length = length;
    work.entries += length;
  }

  search_options search_;
  group_options grouping_;
  std::vector<std::uint32_t> groups_;
  std::uint64_t groups_build_ = 0;  // the tree build groups_ belong to (0: none kept)
  std::vector<std::uint32_t> walked_;
  // Group g holds particles [bounds[g], bounds[g + 1]) (the groups partition them in order):
  // find_groups_with_targets reads them as a stream rather than from the nodes.
  std::vector<std::uint32_t> group_bounds_;
  std::vector<std::uint32_t> group_stack_;
  std::vector<workspace> workspaces_;
  neighbour_list_builder builder_;
};

// Compiled once per dimension in group_walk.cc.
extern template class group_walk<1>;
extern template class group_walk<2>;
extern template class group_walk<3>;

}  // namespace flecsi_lite::topology::ntree
