// The distributed gravity tree: a locally essential tree per rank (Salmon 1991; Warren & Salmon
// 1993) on which gravity.hh's walk gives every rank's particles the field of the global tree,
// bitwise the same for any number of ranks (docs/programming-model.md, "Distributed gravity").
#pragma once

#include "flecsi_lite/topology/ntree/gravity/detail/gravity_top_tree.hh"
#include "flecsi_lite/topology/ntree/gravity/gravity.hh"
#include "flecsi_lite/topology/ntree/sfc/keys.hh"
#include "flecsi_lite/topology/ntree/space.hh"
#include "flecsi_lite/topology/ntree/tree/hashed_tree.hh"

#include <mpi.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace flecsi_lite::topology::ntree {

/// T is the tree hashed_tree would build from ALL ranks' particles (options.bucket_size). Each
/// rank holds the straddling top of T, its own part of T, and the nodes and particles of the
/// other ranks' parts that its target groups' walks reach; the walk on that tree visits the same
/// nodes with the same data in the same order as on T, hence the same sums to the bit.
///
///   gravity_tree<3> tree;
///   tree.build(keys, x, m, h, nullptr, n, options, comm);   // collective
///   tree.evaluate(newtonian, acceleration, potential);      // local
template<int D>
class gravity_tree {
 public:
  /// Collective over comm. The n owned particles of this rank, in (key, id) order, the ranks'
  /// particles concatenated in rank order being the global (key, id) order (as ntree::distribute()
  /// leaves them; keys = the ntree's `key` field, full depth). acceleration_old: |a| per particle
  /// (nullable; needed with options.relative_criterion). The arrays are copied.
  void build(const key_type* keys, const point<D>* x, const double* m, const double* h, const double* acceleration_old,
             std::size_t n, const gravity_options& options, MPI_Comm comm);

  /// Accelerations and potentials (G = 1) of the n owned particles, in their order: bitwise equal
  /// for any number of ranks. Not collective (all communication happens in build). With `wanted`
  /// (n flags, nullable) only the target groups holding a wanted particle are walked: the wanted
  /// particles get the same bits, some others keep what the arrays held (gravity_targets).
  template<class Near>
  gravity_counts evaluate(const Near& near, point<D>* acceleration, double* potential,
                          const std::uint8_t* wanted = nullptr) const {
    gravity_targets<D> targets;
    targets.x = owned_x_.data();
    targets.h = owned_h_.data();
    targets.wanted = wanted;
    return gravity_walk<D>(sources(), groups_, targets, options_, near, acceleration, potential);
  }

  /// What build received from other ranks (top-tree nodes and straddling leaves' particles
  /// included), for the statistics and the benchmark.
  std::size_t imported_nodes() const { return imported_nodes_; }
  std::size_t imported_particles() const { return imported_particles_; }
  /// Target-group records build sent (one per group and rank whose subtrees its walk opens).
  std::size_t sent_groups() const { return essential_.sent_groups; }

  /// The source tree the walk runs on (on one rank: the local tree).
  gravity_sources<D> sources() const;
  /// This rank's target groups (indices into its owned particles).
  const std::vector<target_group<D>>& groups() const { return groups_; }
  /// The tree of this rank's owned particles alone (T restricted to them).
  const hashed_tree<D>& local_tree() const { return local_; }
  /// Nodes of the top tree shared by all ranks (0 on one rank).
  std::size_t top_nodes() const { return top_nodes_; }
  std::size_t size() const { return owned_x_.size(); }

 private:
  gravity_options options_;
  std::vector<point<D>> owned_x_;
  std::vector<double> owned_m_, owned_h_;
  hashed_tree<D> local_;
  std::vector<target_group<D>> groups_;
  bool local_only_ = true;  // the local tree is the whole source tree (one rank)
  detail::essential_sources<D> essential_;
  std::size_t imported_nodes_ = 0, imported_particles_ = 0, top_nodes_ = 0;
};

extern template class gravity_tree<1>;
extern template class gravity_tree<2>;
extern template class gravity_tree<3>;

}  // namespace flecsi_lite::topology::ntree
