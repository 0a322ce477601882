// The local tree of a distributed ntree: a hashed tree (Warren & Salmon 1993) over this rank's
// owned and ghost particles together, built on a copy sorted by (key, id) because owned and ghost
// particles interleave in key order, with the map between sorted and storage indices. Searches
// take owned targets and answer in storage indices, neighbours in ascending (key, id) order.
#pragma once

#include "flecsi_lite/execution/forall.hh"
#include "flecsi_lite/topology/ntree/distributed/sorted_runs.hh"
#include "flecsi_lite/topology/ntree/periodic.hh"
#include "flecsi_lite/topology/ntree/search/group_walk.hh"
#include "flecsi_lite/topology/ntree/search/neighbour_lists.hh"
#include "flecsi_lite/topology/ntree/sfc/ordering.hh"
#include "flecsi_lite/topology/ntree/tree/hashed_tree.hh"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <stdexcept>
#include <vector>

namespace flecsi_lite::topology::ntree {

/// Vocabulary: STORAGE index = position in the topology's fields (owned [0, owned), then
/// ghosts); SORTED index = position in the (key, id) order of owned and ghost particles
/// together, which is the tree's particle order.
template<int D>
class local_tree {
 public:
  /// Builds the tree of `total` particles, the first `owned` of them owned, from their storage
  /// arrays, which hold runs already in (key, id) order: run j is [runs[j], runs[j + 1]) (and
  /// the last ends at `total`); the runs are merged. Ids are unique, so the sorted order (and
  /// every search result) does not depend on how the particles are spread over ranks.
  void build(const key_type* keys, const std::uint64_t* ids, const point<D>* x, const double* m, const double* h,
             std::size_t owned, std::size_t total, const std::vector<std::size_t>& runs, const tree_options& options) {
    owned_ = owned;
    merge_sorted_runs(keys, ids, total, runs, sorted_to_storage_);
    storage_to_sorted_.resize(total);
    owned_mask_.resize(total);
    keys_.resize(total);
    ids_.resize(total);
    apply_permutation(sorted_to_storage_, keys, keys_.data());
    apply_permutation(sorted_to_storage_, ids, ids_.data());
    flecsi_lite::forall(
      total,
      [this](std::size_t s) {
        storage_to_sorted_[sorted_to_storage_[s]] = s;
        owned_mask_[s] = sorted_to_storage_[s] < owned_;
      },
      "ntree::local_tree::index");
    // The lists are written in place (find_neighbours), row = storage index of the target.
    for (std::size_t a = 1; a < owned; ++a)
      if (storage_to_sorted_[a - 1] > storage_to_sorted_[a])
        throw std::logic_error("ntree::local_tree: the owned particles are not in (key, id) order");
    gather(x, m, h);
    moved_.assign(total, 0);
    tree_.build(keys_.data(), x_.data(), m_.data(), h_.data(), total, options);
  }

  /// Takes new positions, masses and smoothing lengths of the same particles (storage arrays,
  /// ghosts updated) and recomputes the node boxes and moments; the structure is kept. Only the
  /// nodes holding a particle whose values changed (bit for bit) are recomputed: the nodes are
  /// those of a whole refit, at the cost of a comparison for the particles that did not move.
  void refresh(const point<D>* x, const double* m, const double* h) {
    take_moved(x, m, h);
    tree_.refit_moved(x_.data(), m_.data(), h_.data(), moved_.data());
  }

  const hashed_tree<D>& tree() const { return tree_; }
  std::size_t size() const { return sorted_to_storage_.size(); }
  std::size_t owned_size() const { return owned_; }
  const std::vector<std::size_t>& sorted_to_storage() const { return sorted_to_storage_; }
  const std::vector<std::size_t>& storage_to_sorted() const { return storage_to_sorted_; }
  /// owned_mask()[s] is 1 when sorted particle s is owned (search_options::targets).
  const std::vector<std::uint8_t>& owned_mask() const { return owned_mask_; }
  /// Memory held: the sorted copies, the index maps, the tree and the search workspaces.
  std::size_t bytes() const {
    const std::size_t per_particle = 2 * sizeof(std::size_t) + 2 * sizeof(std::uint8_t) + sizeof(key_type) +
                                     sizeof(std::uint64_t) + sizeof(point<D>) + 2 * sizeof(double);
    return sorted_to_storage_.capacity() * per_particle + tree_.bytes() + walk_.bytes() + target_mask_.capacity() +
           selected_walk_.bytes();
  }
  /// Sorted copies of the particle data the tree was built from.
  const std::vector<key_type>& keys() const { return keys_; }
  const std::vector<std::uint64_t>& ids() const { return ids_; }
  const std::vector<point<D>>& positions() const { return x_; }
  const std::vector<double>& masses() const { return m_; }
  const std::vector<double>& smoothing_lengths() const { return h_; }

  /// Neighbour lists of every owned particle, indexed by its storage index a < owned_size(),
  /// with neighbours (owned or ghost) as storage indices in ascending (key, id) order and their
  /// shift codes stored as `shifts` says. Uses the group walk (seed Algorithm 2), which writes
  /// the lists in place: owned storage order is the sorted order of the owned particles.
  void find_neighbours(interaction kind, double support, const domain<D>& space, neighbour_lists& out,
                       const group_options& groups = {}, shift_storage shifts = shift_storage::separate) {
    walk_for(kind, support, groups).find_neighbours(tree_, space, out, owned_rows(shifts));
  }

  /// The lists of the owned targets with storage_targets[a] != 0 only (one byte per owned
  /// particle; the other rows come out empty), as find_neighbours makes them. The walk skips the
  /// groups without a target, so its cost follows the number of targets (individual time steps
  /// search their active particles only).
  void find_neighbours_of(const std::vector<std::uint8_t>& storage_targets, interaction kind, double support,
                          const domain<D>& space, neighbour_lists& out, const group_options& groups = {},
                          shift_storage shifts = shift_storage::separate) {
    mark_targets(storage_targets);
    reuse_walk(selected_walk_, target_mask_.data(), kind, support, groups)
      .find_neighbours(tree_, space, out, owned_rows(shifts));
  }

  /// Calls apply(a, b, shift) with storage indices for every owned target a and each neighbour
  /// b (the source image is x_b + shift), in parallel over groups of targets; the calls for one
  /// target come from one thread, in ascending (key, id) order of b.
  template<class F>
  void for_each_neighbour(interaction kind, double support, const domain<D>& space, F&& apply,
                          const group_options& groups = {}) {
    const std::size_t* map = sorted_to_storage_.data();
    walk_for(kind, support, groups)
      .for_each_neighbour(tree_, space, [&apply, map](std::size_t a, std::size_t b, const point<D>& shift) {
        apply(map[a], map[b], shift);
      });
  }

 private:
  void gather(const point<D>* x, const double* m, const double* h) {
    const std::size_t n = sorted_to_storage_.size();
    x_.resize(n);
    m_.resize(n);
    h_.resize(n);
    // One loop for the three arrays (one fork and join, one pass over the map).
    const std::size_t* from = sorted_to_storage_.data();
    point<D>* sorted_x = x_.data();
    double *sorted_m = m_.data(), *sorted_h = h_.data();
    flecsi_lite::forall(
      n,
      [=](std::size_t s) {
        sorted_x[s] = x[from[s]];
        sorted_m[s] = m[from[s]];
        sorted_h[s] = h[from[s]];
      },
      "ntree::local_tree::gather");
  }

  // gather for the same particles, marking in moved_ those whose x, m or h differ in any bit from
  // the sorted copies.
  void take_moved(const point<D>* x, const double* m, const double* h) {
    if (moved_.size() != size()) throw std::logic_error("ntree::local_tree: refresh of a tree that was not built");
    const std::size_t* from = sorted_to_storage_.data();
    point<D>* sorted_x = x_.data();
    double *sorted_m = m_.data(), *sorted_h = h_.data();
    std::uint8_t* moved = moved_.data();
    const auto differs = [](double a, double b) { return std::memcmp(&a, &b, sizeof(double)) != 0; };
    flecsi_lite::forall(
      size(),
      [=](std::size_t s) {
        const std::size_t a = from[s];
        bool changed = differs(m[a], sorted_m[s]) || differs(h[a], sorted_h[s]);
        for (int k = 0; k < D; ++k) changed = changed || differs(x[a][k], sorted_x[s][k]);
        moved[s] = changed;
        if (!changed) return;
        sorted_x[s] = x[a];
        sorted_m[s] = m[a];
        sorted_h[s] = h[a];
      },
      "ntree::local_tree::take_moved");
  }

  // target_mask_ in sorted order from a mask over the owned storage indices.
  void mark_targets(const std::vector<std::uint8_t>& storage_targets) {
    const std::size_t count = owned_;
    if (storage_targets.size() < count)
      throw std::logic_error("ntree::local_tree: the target mask has fewer entries than the targets it selects from");
    target_mask_.resize(size());
    const std::size_t* from = sorted_to_storage_.data();
    const std::uint8_t* chosen = storage_targets.data();
    std::uint8_t* mask = target_mask_.data();
    flecsi_lite::forall(
      size(), [=](std::size_t s) { mask[s] = from[s] < count && chosen[from[s]] != 0; },
      "ntree::local_tree::mark_targets");
  }

  // `walk` with `targets` (a sorted-order mask), kept with its workspaces while the options stay
  // the same.
  static group_walk<D>& reuse_walk(group_walk<D>& walk, const std::uint8_t* targets, interaction kind, double support,
                                   const group_options& groups) {
    search_options options;
    options.kind = kind;
    options.support = support;
    options.targets = targets;
    const auto& current = walk.options();
    if (current.kind != kind || current.support != support || current.targets != options.targets ||
        walk.grouping().max_group_size != groups.max_group_size ||
        walk.grouping().max_group_mass != groups.max_group_mass)
      walk = group_walk<D>(options, groups);
    return walk;
  }
  group_walk<D>& walk_for(interaction kind, double support, const group_options& groups) {
    return reuse_walk(walk_, owned_mask_.data(), kind, support, groups);
  }

  // Rows for the owned particles, storage indices (renamed from the sorted order when there are ghosts).
  list_layout owned_rows(shift_storage shifts) const {
    list_layout layout;
    layout.rename = size() > owned_ ? sorted_to_storage_.data() : nullptr;  // without ghosts: no renaming
    layout.rows = owned_;
    layout.shifts = shifts;
    return layout;
  }

  std::size_t owned_ = 0;
  std::vector<std::size_t> sorted_to_storage_, storage_to_sorted_;
  std::vector<std::uint8_t> owned_mask_;
  // Sorted particles whose values changed in the last refresh.
  std::vector<std::uint8_t> moved_;
  std::vector<key_type> keys_;
  std::vector<std::uint64_t> ids_;
  std::vector<point<D>> x_;
  std::vector<double> m_, h_;
  hashed_tree<D> tree_;
  group_walk<D> walk_;
  // The walk over chosen targets (find_neighbours_of) and their mask.
  std::vector<std::uint8_t> target_mask_;
  group_walk<D> selected_walk_;
};

}  // namespace flecsi_lite::topology::ntree
