// The local hashed tree of the ntree topology (Warren & Salmon 1993; Warren 2013, "2HOT"): nodes
// built level by level from particles sorted by key, found by key through a hash table, and a
// bottom-up pass for mass, centre of mass, tight bounding box, largest h and quadrupole.
#pragma once

#include "flecsi_lite/execution/forall.hh"
#include "flecsi_lite/topology/ntree/detail/node_moments.hh"
#include "flecsi_lite/topology/ntree/sfc/keys.hh"
#include "flecsi_lite/topology/ntree/space.hh"
#include "flecsi_lite/topology/ntree/tree/detail/node_table.hh"
#include "flecsi_lite/topology/ntree/tree/detail/search_node.hh"
#include "flecsi_lite/topology/ntree/tree/multipole.hh"

#include <algorithm>
#include <cassert>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <vector>

namespace flecsi_lite::topology::ntree {

struct tree_options {
  /// Most particles in a leaf; a node with more is split, unless it is at the deepest level
  /// (coincident particles share a key, so such a leaf may hold more).
  std::size_t bucket_size = 16;
  /// Also compute the traceless quadrupole of every node about its centre of mass (gravity).
  bool quadrupole = false;
};

/// A node is a cell of the key hierarchy that holds particles. Its particles are the contiguous
/// range [begin, end) of the sorted order; its children (non-empty child cells, in key order)
/// are the contiguous nodes [first_child, first_child + child_count); a leaf has no children.
template<int D>
struct tree_node {
  key_type key = root_key;
  std::uint32_t begin = 0;
  std::uint32_t end = 0;
  std::uint32_t first_child = 0;
  std::uint8_t child_count = 0;
  std::uint8_t level = 0;
  /// Tight box of the particles (not the key cell): searches prune on it, so they stay exact
  /// when particles have moved since their keys were computed (see hashed_tree::refit).
  box<D> bounds = box<D>::empty();
  double h_max = 0;  ///< largest smoothing length of the particles
  double mass = 0;
  point<D> centre{};  ///< centre of mass (centre of the bounds when the mass is zero)

  bool is_leaf() const { return child_count == 0; }
  std::uint32_t size() const { return end - begin; }
};

/// The tree keeps pointers to the particle arrays it was built from (sorted by key, then id);
/// they must outlive it and, once changed, be passed again to refit() before a search.
template<int D>
class hashed_tree {
 public:
  static constexpr std::uint32_t npos = node_table::npos;

  /// Decides whether a node (below the deepest level) is split, from its key, level and range.
  using split_rule = std::function<bool(const tree_node<D>&)>;

  /// Builds the tree of n particles sorted by (key, id): `keys` are their full-depth keys,
  /// `x`, `m`, `h` their positions, masses and smoothing lengths. A node with more than
  /// options.bucket_size particles is split.
  void build(const key_type* keys, const point<D>* x, const double* m, const double* h, std::size_t n,
             const tree_options& options = {});

  /// The same with the split decision given: a node (below the deepest level) is split when
  /// `split(node)` is true. The distributed gravity tree decides so by the global count of a node
  /// whose particles straddle ranks.
  void build(const key_type* keys, const point<D>* x, const double* m, const double* h, std::size_t n,
             const tree_options& options, const split_rule& split);

  /// Recomputes the bottom-up quantities (bounds, h_max, mass, centre, quadrupole) from new
  /// particle data, keeping the structure: valid for the same particles in the same order.
  void refit(const point<D>* x, const double* m, const double* h);

  /// The same when only the particles with moved[b] != 0 (b in the sorted order) may have a new
  /// x, m or h since the last build or refit: only the nodes that hold one are recomputed. Each
  /// node is a function of its particles' values, so the nodes are bitwise refit's, at a cost
  /// that follows the moved particles (with individual time steps a blast moves a few percent).
  void refit_moved(const point<D>* x, const double* m, const double* h, const std::uint8_t* moved);

  /// Names the last build among every build of every tree of the process (from 1): structure
  /// that depends on nodes' ranges only stays valid while it is unchanged (group_walk's groups).
  std::uint64_t build_id() const { return build_id_; }

  /// Number of particles.
  std::size_t size() const { return nodes_.empty() ? 0 : nodes_[0].end; }
  const std::vector<tree_node<D>>& nodes() const { return nodes_; }
  /// The nodes' compact copies for neighbour-search walks (same indices as nodes()).
  const std::vector<search_node<D>>& search_nodes() const { return search_nodes_; }
  const tree_node<D>& node(std::uint32_t index) const { return nodes_[index]; }
  const tree_node<D>& root() const { return nodes_[0]; }
  /// Deepest level holding a node.
  int depth() const { return static_cast<int>(level_begin_.size()) - 2; }
  /// Nodes of level l are the indices [level_begin(l), level_begin(l + 1)).
  std::uint32_t level_begin(int l) const { return level_begin_[l]; }

  /// Index of the node with `key`, or npos (2HOT's key lookup).
  std::uint32_t find(key_type key) const {
    return table_.find(key, [this](std::size_t i) { return nodes_[i].key; });
  }

  bool has_quadrupoles() const { return !quadrupoles_.empty(); }
  const quadrupole<D>& node_quadrupole(std::uint32_t index) const {
    assert(has_quadrupoles());
    return quadrupoles_[index];
  }

  const point<D>* positions() const { return x_; }
  const double* masses() const { return m_; }
  const double* smoothing_lengths() const { return h_; }
  const tree_options& options() const { return options_; }

  /// Memory held by the tree (nodes, hash table, quadrupoles, level index).
  std::size_t bytes() const {
    return nodes_.size() * (sizeof(tree_node<D>) + sizeof(search_node<D>)) + node_moved_.capacity() + table_.bytes() +
           quadrupoles_.size() * sizeof(quadrupole<D>) + level_begin_.size() * sizeof(std::uint32_t);
  }

 private:
  std::size_t level_size(int l) const { return level_begin_[l + 1] - level_begin_[l]; }

  // Splits the nodes [first, last) (one level) and appends their children; returns how many.
  std::size_t split_level(const key_type* keys, std::size_t first, std::size_t last, const split_rule& split);
  // Bottom-up quantities of one node; its children are already done.
  void compute_node(std::size_t index);
  // Calls update(i) for every node, deepest level first (a level in parallel).
  template<class Update>
  void for_each_node_bottom_up(const Update& update);

  tree_options options_;
  std::vector<tree_node<D>> nodes_;
  std::vector<search_node<D>> search_nodes_;
  std::vector<std::uint32_t> level_begin_;
  std::vector<quadrupole<D>> quadrupoles_;
  node_table table_;
  const point<D>* x_ = nullptr;
  const double* m_ = nullptr;
  const double* h_ = nullptr;
  std::uint64_t build_id_ = 0;
  std::vector<std::uint8_t> node_moved_;  // refit_moved: whether a node holds a moved particle
  // Build scratch, kept to avoid reallocation on rebuilds.
  std::vector<std::uint32_t> child_begin_;
  std::vector<std::uint32_t> child_offset_;
};

// Compiled once per dimension in hashed_tree.cc, where build and refit are defined.
extern template class hashed_tree<1>;
extern template class hashed_tree<2>;
extern template class hashed_tree<3>;

}  // namespace flecsi_lite::topology::ntree
