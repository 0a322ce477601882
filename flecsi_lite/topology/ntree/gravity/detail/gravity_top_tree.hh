// Internals of the distributed gravity tree (locally essential trees, Salmon 1991; Warren &
// Salmon 1993): the cells that straddle ranks, the shared top tree, the wire records of nodes and
// particles, and the exchange steps (defined in distributed/gravity_top_tree.cc, gravity_essential.cc).
#pragma once

#include "flecsi_lite/topology/ntree/gravity/gravity.hh"
#include "flecsi_lite/topology/ntree/sfc/keys.hh"
#include "flecsi_lite/topology/ntree/tree/hashed_tree.hh"
#include "flecsi_lite/topology/ntree/tree/multipole.hh"

#include <mpi.h>

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace flecsi_lite::topology::ntree::detail {

/// A cell holding particles of more than one rank: a common ancestor of the last key of a rank
/// and the first key of the next non-empty one. Its numbers are global (summed over ranks).
struct straddling_cell {
  key_type key = root_key;
  std::uint64_t begin = 0;      ///< global (key, id) index of its first particle
  std::uint64_t count = 0;      ///< its particles on all ranks
  double acceleration_min = 0;  ///< smallest |a_old| of its particles (0 when not given)
  bool in_tree = false;         ///< a node of the global tree T (every ancestor is split)
  bool split = false;           ///< T splits it (a node of T with more than bucket_size particles)
};

/// The straddling cells, sorted by key (hence by level), known identically to every rank.
class straddling_cells {
 public:
  static constexpr std::size_t npos = ~std::size_t{0};

  /// Collective: allgather of each rank's first and last key, then one integer and one min
  /// reduction for the cells' counts and smallest old accelerations. keys (sorted), n and
  /// acceleration_old (nullable) are this rank's particles.
  template<int D>
  void find(const key_type* keys, const double* acceleration_old, std::size_t n, std::size_t bucket_size,
            MPI_Comm comm);

  std::size_t size() const { return cells_.size(); }
  bool empty() const { return cells_.empty(); }
  const straddling_cell& operator[](std::size_t i) const { return cells_[i]; }
  /// Index of the cell with `key`, or npos.
  std::size_t index(key_type key) const;

 private:
  std::vector<straddling_cell> cells_;
};

/// A node as sent between ranks: what the walk reads of it (tree_node's bottom-up quantities,
/// size, children count) and its quadrupole; `opened` tells the receiver that its children (or
/// its particles, for a leaf) follow.
template<int D>
struct wire_node {
  key_type key = root_key;
  box<D> bounds;
  point<D> centre;
  double h_max = 0, mass = 0;
  std::array<double, D * D> q{};
  std::uint32_t size = 0;
  std::int32_t owner = -1;
  std::uint8_t level = 0, child_count = 0, opened = 0;
};

template<int D>
wire_node<D> to_wire(const tree_node<D>& node, const quadrupole<D>* q, int owner);
/// The node (begin 0, end size, first_child 0) and its quadrupole (when `q` is not nullptr).
template<int D>
tree_node<D> from_wire(const wire_node<D>& record, quadrupole<D>* q);

/// A particle as sent between ranks; `leaf` names the straddling leaf it belongs to.
template<int D>
struct wire_particle {
  key_type leaf = root_key;
  point<D> x;
  double m = 0, h = 0;
};

/// Collective: every rank's `mine` in rank order (MPI_Allgatherv of bytes); `counts`, if given,
/// receives how many came from each rank.
template<class T>
std::vector<T> allgather_records(const std::vector<T>& mine, MPI_Comm comm, std::vector<int>* counts = nullptr);

/// The top of T that every rank holds identically: the straddling nodes of T and their
/// children, breadth first, children contiguous in key order (node 0 the root). A child that
/// does not straddle is the root of a SUBTREE all on one rank, its `owner`; it is as that rank's
/// local tree computed it, with its size as [0, size) and its children left out. A straddling
/// node has owner -1; its moments come from detail/node_moments.hh, from its children or, for
/// a leaf, from its particles gathered in global order (particles [begin, end) of x, m, h);
/// a straddling inner node has the global range [begin, begin + count).
/// Without straddling cells (at most one rank holds particles) it is that rank's root alone.
template<int D>
struct top_tree {
  std::vector<tree_node<D>> nodes;
  std::vector<quadrupole<D>> quadrupoles;  ///< per node, when the tree has quadrupoles
  std::vector<std::int32_t> owner;
  std::vector<std::uint32_t> local;  ///< the node's index in this rank's local tree, or npos
  std::vector<point<D>> x;
  std::vector<double> m, h;
  std::size_t nodes_from_others = 0, particles_from_others = 0;
};

/// Collective: the top tree from the local tree (built with the straddling cells' split rule);
/// `with_quadrupoles` as the local tree was built.
template<int D>
top_tree<D> build_top_tree(const hashed_tree<D>& local, const straddling_cells& cells, bool with_quadrupoles, int rank,
                           MPI_Comm comm);

/// This rank's target groups of T (gravity.hh's rule on T's node sizes): groups inside its own
/// subtrees from its local tree, and a group for each straddling group node where it holds
/// particles, with the node's global bounds, h_max and smallest old acceleration.
template<int D>
std::vector<target_group<D>> essential_groups(const top_tree<D>& top, const hashed_tree<D>& local,
                                              const straddling_cells& cells, const double* acceleration_old,
                                              std::size_t group_size, int rank);

/// What a rank walks for the others' groups: the criteria data of a target group.
template<int D>
struct group_record {
  box<D> bounds;
  double h_max = 0, acceleration_min = 0;
};

/// The locally essential tree's imports, decoded into the source tree of this rank (see
/// gravity_tree::build): nodes and quadrupoles appended, particles appended to x, m, h.
template<int D>
struct essential_sources {
  std::vector<tree_node<D>> nodes;
  std::vector<quadrupole<D>> quadrupoles;
  std::vector<point<D>> x;
  std::vector<double> m, h;
  std::size_t imported_nodes = 0, imported_particles = 0;
  std::size_t sent_groups = 0;  ///< group records this rank sent (one per group and rank it needs)
};

/// Collective: sends each group's record to the ranks owning a subtree root that its walk over
/// the top tree opens; walks each other rank s's groups so received over the top tree and its own
/// subtrees with gravity_accepts, and returns to s the
/// nodes below its subtree roots that s's walks reach (children of every opened node, with
/// their moments) and the particles of the leaves they open; assembles the top tree, the local
/// tree and the imports into `out` (owned particles first, the local tree's ranges kept).
template<int D>
void assemble_essential_tree(const top_tree<D>& top, const hashed_tree<D>& local,
                             const std::vector<target_group<D>>& groups, const gravity_options& options, int rank,
                             MPI_Comm comm, essential_sources<D>& out);

}  // namespace flecsi_lite::topology::ntree::detail
