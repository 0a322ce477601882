// hashed_tree<D> compiled once per dimension (hashed_tree.hh declares it extern): every program
// builds the same local tree, so its build and refit are defined here, out of the class, and their
// code is generated once rather than in every translation unit that holds a tree.
#include "flecsi_lite/topology/ntree/tree/hashed_tree.hh"

#include <algorithm>
#include <atomic>
#include <cassert>

namespace flecsi_lite::topology::ntree {

template<int D>
void hashed_tree<D>::build(const key_type* keys, const point<D>* x, const double* m, const double* h, std::size_t n,
                           const tree_options& options) {
  const std::size_t bucket = options.bucket_size;
  build(keys, x, m, h, n, options, [bucket](const tree_node<D>& node) { return node.size() > bucket; });
}

template<int D>
void hashed_tree<D>::build(const key_type* keys, const point<D>* x, const double* m, const double* h, std::size_t n,
                           const tree_options& options, const split_rule& split) {
  assert(options.bucket_size >= 1);
  assert(n < npos);
#ifndef NDEBUG
  for (std::size_t i = 0; i < n; ++i) assert(level<D>(keys[i]) == max_level<D>);
  for (std::size_t i = 1; i < n; ++i) assert(keys[i - 1] <= keys[i]);
#endif
  static std::atomic<std::uint64_t> builds{0};
  build_id_ = ++builds;
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

template<int D>
template<class Update>
void hashed_tree<D>::for_each_node_bottom_up(const Update& update) {
  // Levels of few nodes are done in place: a parallel loop costs a fork and a join, which on
  // a loaded machine can wait for a thread that is not running.
  constexpr std::size_t parallel_level_size = 1024;
  for (int l = depth(); l >= 0; --l) {
    if (level_size(l) < parallel_level_size) {
      for (std::uint32_t i = level_begin_[l]; i < level_begin_[l + 1]; ++i) update(i);
    } else {
      flecsi_lite::forall(
        level_size(l), [&update, this, l](std::size_t i) { update(level_begin_[l] + i); }, "ntree::hashed_tree::refit");
    }
  }
}

template<int D>
void hashed_tree<D>::refit(const point<D>* x, const double* m, const double* h) {
  x_ = x;
  m_ = m;
  h_ = h;
  quadrupoles_.assign(options_.quadrupole ? nodes_.size() : 0, quadrupole<D>::Zero());
  search_nodes_.resize(nodes_.size());
  for_each_node_bottom_up([this](std::size_t i) { compute_node(i); });
}

template<int D>
void hashed_tree<D>::refit_moved(const point<D>* x, const double* m, const double* h, const std::uint8_t* moved) {
  x_ = x;
  m_ = m;
  h_ = h;
  node_moved_.resize(nodes_.size());
  std::uint8_t* node_moved = node_moved_.data();
  for_each_node_bottom_up([this, moved, node_moved](std::size_t i) {
    const tree_node<D>& node = nodes_[i];
    std::uint8_t any = 0;
    if (node.is_leaf()) {
      for (std::uint32_t b = node.begin; b < node.end; ++b) any |= moved[b];
    } else {
      for (std::uint32_t c = node.first_child; c < node.first_child + node.child_count; ++c) any |= node_moved[c];
    }
    node_moved[i] = any;
    if (any) compute_node(i);
  });
}

template<int D>
std::size_t hashed_tree<D>::split_level(const key_type* keys, std::size_t first, std::size_t last,
                                        const split_rule& split) {
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

// The sums are the shared ones of detail/node_moments.hh (the distributed gravity tree computes
// its top nodes with them).
template<int D>
void hashed_tree<D>::compute_node(std::size_t index) {
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

template class hashed_tree<1>;
template class hashed_tree<2>;
template class hashed_tree<3>;
}  // namespace flecsi_lite::topology::ntree
