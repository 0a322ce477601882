// The distributed ntree topology: particles spread over the ranks by a parallel sample sort of
// their space-filling-curve keys, ghosts found by branch sharing, and a local hashed tree over
// owned and ghost particles for searches (FleCSPH, seed sec. 2.3; Warren & Salmon 1993).
#pragma once

#include "flecsi_lite/data/field.hh"
#include "flecsi_lite/data/topology_base.hh"
#include "flecsi_lite/data/tracked.hh"
#include "flecsi_lite/execution/execute.hh"
#include "flecsi_lite/runtime/context.hh"
#include "flecsi_lite/topology/ntree/distributed/distribution_stats.hh"
#include "flecsi_lite/topology/ntree/periodic.hh"
#include "flecsi_lite/topology/ntree/search/neighbour_lists.hh"
#include "flecsi_lite/topology/ntree/sfc/keys.hh"
#include "flecsi_lite/topology/ntree/space.hh"
#include "flecsi_lite/topology/ntree/tree/hashed_tree.hh"
#include "flecsi_lite/topology/ntree/tree/local_tree.hh"

#include <array>
#include <cstddef>
#include <cstdint>
#include <optional>
#include <utility>
#include <vector>

namespace flecsi_lite::topology::ntree {

template<int D>
class ntree;
template<int D>
struct branch;

/// How distribute() balances the ranks: equal particle counts, or equal sums of a per-particle
/// work weight (e.g. the neighbour count of the last search, as FleCSPH offers).
enum class balance { count, work };

template<int D>
struct ntree_config {
  curve order = curve::hilbert;
  /// Most particles in a leaf of the local tree.
  std::size_t bucket_size = 16;
  /// Periodic axes; a periodic domain needs `fixed_box` (the period is its side) and particles
  /// inside it along the periodic axes.
  std::array<bool, D> periodic{};
  /// Box of the keys; without it, the global bounding box of the particles (slightly padded).
  std::optional<box<D>> fixed_box;
  /// Bytes of keys each rank sends to rank 0 as its sample (seed: 256 KB).
  std::size_t sample_bytes = 256 * 1024;
  balance balancing = balance::count;
  /// Per-particle weight (>= 0) for balance::work; also reported in the statistics when set.
  const typename field<double>::template definition<ntree<D>>* work_weight = nullptr;
  /// Interaction reach in units of h: particles a, b interact when |x_a - x_b| < support *
  /// max(h_a, h_b) (symmetric) or < support * h_a (gather).
  double support = 2.0;
  /// Ghosts are selected with reach support * ghost_reach_factor (>= 1): room for h to grow
  /// before the next distribute().
  double ghost_reach_factor = 1.0;
  /// Most top branches each rank shares: more give tighter boxes and fewer ghosts.
  std::size_t branch_count = 1024;
};

/// A distributed set of particles in D dimensions (D = 1, 2, 3). Vocabulary, per rank (seed
/// Fig. 2.3): OWNED particles live here [0, owned_size()) and are EXCLUSIVE (needed by no other
/// rank) or SHARED (copied to others); GHOST particles [owned_size(), total_size()) are copies of
/// particles owned elsewhere, within reach of this rank's particles, ordered by source rank,
/// then (key, id). Every field defined on ntree<D> follows its particles through distribute().
template<int D>
class ntree : public data::topology_base {
 public:
  using config = ntree_config<D>;
  using point_type = point<D>;

  template<class T>
  using definition = typename field<T>::template definition<ntree>;

  // Built-in fields, with their persistence (data/persistence.hh): written to outputs and
  // checkpoints as x y z (zeros beyond D), id, m, h, and read from initial data (id optional:
  // the particle's index in the file), with their units and SWIFT names. The key does not
  // persist: distribute() recomputes it.
  static inline const definition<point<D>> position{
    "position", persist::as("x", "y", "z")
                  .padded()
                  .output()
                  .restart()
                  .initial_required(persist::must_be_finite("positions"))
                  .units(0, 1, 0)
                  .in_snapshots("Coordinates", "Positions of the particles (3 columns; zeros beyond the dimension)")
                  .in_swift_initial_conditions("Coordinates")};
  static inline const definition<std::uint64_t> id{"id",
                                                   persist::output()
                                                     .restart()
                                                     .initial_optional_index()
                                                     .in_snapshots("ParticleIDs", "Unique identifiers of the particles")
                                                     .in_swift_initial_conditions("ParticleIDs")};  ///< unique
  static inline const definition<double> mass{"mass", persist::as("m")
                                                        .output()
                                                        .restart()
                                                        .initial_required(persist::must_be_positive("masses"))
                                                        .units(1, 0, 0)
                                                        .in_snapshots("Masses", "Masses of the particles")
                                                        .in_swift_initial_conditions("Masses")};
  /// A particle reaches settings().support h (2 h by default, Monaghan's M4 convention); SWIFT's
  /// h is that reach over its kernel_gamma (Dehnen & Aly 2012).
  static inline const definition<double> smoothing_length{
    "h", persist::output()
           .restart()
           .initial_required(persist::must_be_positive("smoothing lengths"))
           .units(0, 1, 0)
           .in_snapshots("SmoothingLengths",
                         "Smoothing lengths h of the particles; the kernel support radius is 2 h for every kernel "
                         "(SWIFT's h is support / kernel_gamma)")
           .in_swift_initial_conditions("SmoothingLength")};
  static inline const definition<key_type> key{"key"};  ///< set by distribute()

  explicit ntree(const config& settings = config{});
  /// Collective: a tree with `local_count` owned particles here (fields zero).
  ntree(const config& settings, std::size_t local_count);

  /// Collective: sets the number of owned particles here (values of the first min(old, new)
  /// kept), drops ghosts, plan and local tree. Fill the fields (by tasks), then distribute().
  void resize(std::size_t local_count);

  /// Collective: keys, sample sort, all-to-all of all fields, local sort by (key, id), branch
  /// sharing, ghosts (plan set; the executor copies the built-in fields' ghosts for the local
  /// tree task, other fields' on their first ghost read) and the local tree. Afterwards the
  /// owned particles of rank 0, 1, ... concatenated are in increasing (key, id) order.
  distribution_stats distribute();

  const config& settings() const { return config_; }
  /// The box keys were computed in, and the search domain (that box, with periodic axes).
  const box<D>& key_box() const { return space_.bounds; }
  const domain<D>& space() const { return space_; }
  std::uint64_t global_size() const { return global_size_; }
  /// Number of owned particles on lower ranks: after distribute(), owned particle i is the
  /// (first_global_index() + i)-th in the global (key, id) order.
  std::uint64_t first_global_index() const { return first_global_index_; }
  std::size_t exclusive_size() const { return exclusive_; }
  std::size_t shared_size() const { return owned_size() - exclusive_; }
  /// Every rank's top branches as shared by the last distribute(), indexed by rank.
  const std::vector<std::vector<branch<D>>>& branches() const { return branches_; }

  /// The tree over owned and ghost particles and its sorted/storage index maps, outside tasks
  /// (once the pending tasks, which may refit it, have run).
  const local_tree<D>& local() const { return local_.host(); }
  local_tree<D>& local() { return local_.host(); }
  const hashed_tree<D>& tree() const { return local().tree(); }
  const std::vector<std::size_t>& sorted_to_storage() const { return local().sorted_to_storage(); }
  /// The local tree as the executor tracks it, for tasks: pass it to a parameter
  /// tracked<local_tree<D>>::accessor<ro> (searches that keep workspaces need rw).
  tracked<local_tree<D>>& local_tree_object() { return local_; }

  /// Neighbour lists of the owned particles (storage indices; neighbours in ascending (key, id)
  /// order, so sums over them do not depend on the rank count), reach settings().support, with
  /// the image shift codes stored as `shifts` says.
  void find_neighbours(neighbour_lists& out, interaction kind = interaction::symmetric,
                       shift_storage shifts = shift_storage::separate) {
    local().find_neighbours(kind, config_.support, space_, out, {}, shifts);
  }
  /// apply(a, b, shift) for every owned a and neighbour b (storage indices), called in parallel
  /// over groups of targets (the calls for one a come from one thread), see local_tree.
  template<class F>
  void for_each_neighbour(F&& apply, interaction kind = interaction::symmetric) {
    local().for_each_neighbour(kind, config_.support, space_, std::forward<F>(apply));
  }
  /// Refits the local tree to the current positions, masses and smoothing lengths of the same
  /// particles (owned values changed since distribute()): launches a task reading them with
  /// ghosts, so stale ghost values are copied first; tasks using the tree run after it.
  void refresh_local_tree();

 private:
  template<class T>
  data::field_storage<T>& values(const typename field<T>::template definition<ntree>& f) {
    return this->template storage<T>(f.id(), f.name());
  }
  void check_periodic_reach(std::size_t n, MPI_Comm comm);
  box<D> find_key_box(const point<D>* x, std::size_t n, MPI_Comm comm) const;
  std::vector<std::vector<std::size_t>> find_ghost_sends(std::size_t& branch_count);
  void build_local_tree();

  config config_;
  domain<D> space_;
  std::uint64_t global_size_ = 0, first_global_index_ = 0;
  std::size_t exclusive_ = 0;
  std::vector<std::vector<branch<D>>> branches_;
  tracked<local_tree<D>> local_{"ntree local tree"};
};

}  // namespace flecsi_lite::topology::ntree

#include "flecsi_lite/topology/ntree/detail/ntree_definitions.hh"

namespace flecsi_lite::topology::ntree {
// Compiled once per dimension in ntree.cc.
extern template class ntree<1>;
extern template class ntree<2>;
extern template class ntree<3>;
}  // namespace flecsi_lite::topology::ntree
