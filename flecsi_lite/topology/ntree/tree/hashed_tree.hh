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

  /// Builds the tree of n particles sorted by (key, id): `keys` are their full-depth keys,
  /// `x`, `m`, `h` their positions, masses and smoothing lengths.
  void build(const key_type* keys, const point<D>* x, const double* m, const double* h, std::size_t n,
             const tree_options& options = {}) {
    const std::size_t bucket = options.bucket_size;
    build(keys, x, m, h, n, options, [bucket](const tree_node<D>& node) { return node.size() > bucket; });
  }

  /// The same with the split decision given: a node (below the deepest level) is split when
  /// `split(node)` is true, called with its key, level and range here. The distributed gravity
  /// tree decides so by the global count of a node whose particles straddle ranks.
  template<class SplitRule>
  void build(const key_type* keys, const point<D>* x, const double* m, const double* h, std::size_t n,
             const tree_options& options, const SplitRule& split) {
    assert(options.bucket_size >= 1);
    assert(n < npos);
#ifndef NDEBUG
    for (std::size_t i = 0; i < n; ++i) assert(level<D>(keys[i]) == max_level<D>);
    for (std::size_t i = 1; i < n; ++i) assert(keys[i - 1] <= keys[i]);
#endif
    options_ = options;
    nodes_.clear();
    level_begin_.assign(1, 0);
    tree_node<D> root;
    root.end = static_cast<std::uint32_t>(n);
    nodes_.push_back(root);
    for (std::size_t first = 0, last = 1; first < last;) {
      level_begin_.push_back(static_cast<std::uint32_t>(last));
      const std::size_t added = split_level(keys, first, last, split);
      first = last;
      last += added;
    }
    // The last pass found no children; the begin it pushed is the end of the deepest level.

    table_.build(nodes_.size(), [this](std::size_t i) { return nodes_[i].key; });
    refit(x, m, h);
  }

  /// Recomputes the bottom-up quantities (bounds, h_max, mass, centre, quadrupole) from new
  /// particle data, keeping the structure: valid for the same particles in the same order.
  void refit(const point<D>* x, const double* m, const double* h) {
    x_ = x;
    m_ = m;
    h_ = h;
    quadrupoles_.assign(options_.quadrupole ? nodes_.size() : 0, quadrupole<D>::Zero());
    search_nodes_.resize(nodes_.size());
    // Levels of few nodes are done in place: a parallel loop costs a fork and a join, which on
    // a loaded machine can wait for a thread that is not running.
    constexpr std::size_t parallel_level_size = 1024;
    for (int l = depth(); l >= 0; --l) {
      if (level_size(l) < parallel_level_size) {
        for (std::uint32_t i = level_begin_[l]; i < level_begin_[l + 1]; ++i) compute_node(i);
      } else {
        flecsi_lite::forall(
          level_size(l), [this, l](std::size_t i) { compute_node(level_begin_[l] + i); }, "ntree::hashed_tree::refit");
      }
    }
  }

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
    return nodes_.size() * (sizeof(tree_node<D>) + sizeof(search_node<D>)) + table_.bytes() +
           quadrupoles_.size() * sizeof(quadrupole<D>) + level_begin_.size() * sizeof(std::uint32_t);
  }

 private:
  std::size_t level_size(int l) const { return level_begin_[l + 1] - level_begin_[l]; }

  // Splits the nodes [first, last) (one level) and appends their children; returns how many.
  template<class SplitRule>
  std::size_t split_level(const key_type* keys, std::size_t first, std::size_t last, const SplitRule& split) {
    constexpr unsigned children = children_per_cell<D>;
    const std::size_t count = last - first;
    child_begin_.resize(count * (children + 1));
    child_offset_.resize(count);
    flecsi_lite::forall(
      count,
      [&](std::size_t i) {
        const tree_node<D>& parent = nodes_[first + i];
        std::uint32_t* bound = child_begin_.data() + i * (children + 1);
        std::uint32_t nonempty = 0;
        if (parent.level < max_level<D> && split(parent)) {
          // Particles of child c are those whose key has child(parent.key, c) as prefix; sorted
          // keys make each such range contiguous, found by binary search on the shifted prefix.
          const int below = D * (max_level<D> - parent.level - 1);
          bound[0] = parent.begin;
          for (unsigned c = 1; c < children; ++c) {
            const key_type first_key = child<D>(parent.key, c) << below;
            bound[c] =
              static_cast<std::uint32_t>(std::lower_bound(keys + bound[c - 1], keys + parent.end, first_key) - keys);
          }
          bound[children] = parent.end;
          for (unsigned c = 0; c < children; ++c) nonempty += bound[c + 1] > bound[c];
        }
        child_offset_[i] = nonempty;
      },
      "ntree::hashed_tree::split");
    const std::size_t added = flecsi_lite::exclusive_scan(child_offset_.data(), count, "ntree::hashed_tree::offsets");
    nodes_.resize(last + added);
    flecsi_lite::forall(
      count,
      [&](std::size_t i) {
        tree_node<D>& parent = nodes_[first + i];
        const std::uint32_t next = i + 1 < count ? child_offset_[i + 1] : static_cast<std::uint32_t>(added);
        parent.first_child = static_cast<std::uint32_t>(last + child_offset_[i]);
        parent.child_count = static_cast<std::uint8_t>(next - child_offset_[i]);
        if (parent.is_leaf()) return;
        const std::uint32_t* bound = child_begin_.data() + i * (children + 1);
        std::uint32_t at = parent.first_child;
        for (unsigned c = 0; c < children; ++c) {
          if (bound[c + 1] == bound[c]) continue;
          tree_node<D>& node = nodes_[at++];
          node = tree_node<D>{};
          node.key = child<D>(parent.key, c);
          node.begin = bound[c];
          node.end = bound[c + 1];
          node.level = static_cast<std::uint8_t>(parent.level + 1);
        }
      },
      "ntree::hashed_tree::link");
    return added;
  }

  // Bottom-up quantities of one node; its children are already done. The sums are the shared
  // ones of detail/node_moments.hh (the distributed gravity tree computes its top nodes with them).
  void compute_node(std::size_t index) {
    tree_node<D>& node = nodes_[index];
    quadrupole<D>* q = quadrupoles_.empty() ? nullptr : &quadrupoles_[index];
    if (node.is_leaf()) {
      detail::compute_leaf_moments<D>(node, x_, m_, h_, q);
    } else {
      detail::compute_parent_moments<D>(node, nodes_.data(), q ? quadrupoles_.data() : nullptr, q);
    }
    search_node<D>& compact = search_nodes_[index];
    for (int k = 0; k < D; ++k) {
      compact.lo[k] = float_below(node.bounds.lo[k]);
      compact.hi[k] = float_above(node.bounds.hi[k]);
    }
    compact.h_max = float_above(node.h_max);
    compact.begin = node.begin;
    compact.end = node.end;
    compact.first_child = node.first_child;
    compact.child_count = node.child_count;
  }

  tree_options options_;
  std::vector<tree_node<D>> nodes_;
  std::vector<search_node<D>> search_nodes_;
  std::vector<std::uint32_t> level_begin_;
  std::vector<quadrupole<D>> quadrupoles_;
  node_table table_;
  const point<D>* x_ = nullptr;
  const double* m_ = nullptr;
  const double* h_ = nullptr;
  // Build scratch, kept to avoid reallocation on rebuilds.
  std::vector<std::uint32_t> child_begin_;
  std::vector<std::uint32_t> child_offset_;
};

// Compiled once per dimension in hashed_tree.cc.
extern template class hashed_tree<1>;
extern template class hashed_tree<2>;
extern template class hashed_tree<3>;

}  // namespace flecsi_lite::topology::ntree
