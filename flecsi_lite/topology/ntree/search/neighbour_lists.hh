// Vocabulary shared by the ntree neighbour searches: the pair criterion (gather or symmetric
// radius in units of h), search options, and neighbour lists in compressed sparse row form with
// their layouts (image shift codes separate or packed into the entries, renamed rows).
#pragma once

#include "flecsi_lite/execution/forall.hh"
#include "flecsi_lite/execution/shared_argument.hh"
#include "flecsi_lite/topology/ntree/periodic.hh"
#include "flecsi_lite/topology/ntree/search/packed_entries.hh"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace flecsi_lite::topology::ntree {

/// Targets are the particles whose neighbours are sought; sources are all particles of the tree
/// (owned and ghost). A source b is a neighbour of target a when |x_a - (x_b + s)| < R for an
/// image shift s, with
///   gather:    R = support * h_a            (the particles inside a's kernel), or
///   symmetric: R = support * max(h_a, h_b)  (pairs where either kernel reaches the other).
enum class interaction { gather, symmetric };

/// The radius R of the pair (a, b); every search and the brute-force reference use it.
template<interaction Kind>
inline double interaction_radius(double support, double h_target, double h_source) {
  if constexpr (Kind == interaction::gather) {
    (void)h_source;
    return support * h_target;
  } else {
    return support * std::max(h_target, h_source);
  }
}

inline double interaction_radius(interaction kind, double support, double h_target, double h_source) {
  return kind == interaction::gather ? interaction_radius<interaction::gather>(support, h_target, h_source)
                                     : interaction_radius<interaction::symmetric>(support, h_target, h_source);
}

/// The pair criterion: strictly inside the radius.
inline bool within_radius(double distance_squared, double radius) { return distance_squared < radius * radius; }

struct search_options {
  interaction kind = interaction::gather;
  /// Radius of the kernel's compact support in units of h.
  double support = 2.0;
  /// targets[i] != 0 marks particle i (sorted order) as a target; nullptr makes all targets.
  const std::uint8_t* targets = nullptr;

  bool is_target(std::size_t i) const { return targets == nullptr || targets[i] != 0; }
};

/// Where neighbour lists keep the image shift code of each entry (periodic domains):
///   separate  in neighbour_lists::shifts, one byte per entry;
///   packed    in the top 32 - packed_index_bits = 5 bits of the entry itself (packed_entry), on every
///             domain (zero_shift when it is not periodic): 4 bytes per entry, at most 2^27
///             particles in the tree;
///   runs      packed entries, each row coded as runs of consecutive neighbours in
///             neighbour_lists::runs (packed_entries.hh): about 1 byte per entry, read a row
///             with runs::decode_row.
enum class shift_storage { separate, packed, runs };

/// Neighbours of every target in compressed sparse row form: those of particle a are
/// neighbours[offsets[a] .. offsets[a + 1]), in ascending sorted index; a non-target has none.
/// With a periodic domain, shifts[j] is the image shift code of entry j (x_b + shift), unless
/// the codes are packed into the entries (shift_storage::packed). Lists kept as runs
/// (shift_storage::runs) have no `neighbours`: row a is coded in runs[offsets[a] .. offsets[a + 1]),
/// no bytes for a non-target.
struct neighbour_lists {
  std::vector<std::size_t> offsets{0};
  std::vector<std::uint32_t> neighbours;
  std::vector<shift_code> shifts;
  std::vector<std::uint8_t> runs;
  bool in_runs = false;         ///< whether the rows are coded in `runs`
  std::size_t run_entries = 0;  ///< the entries of all rows coded in `runs`

  std::size_t size() const { return offsets.size() - 1; }
  std::size_t count(std::size_t a) const {
    if (!in_runs || offsets[a + 1] == offsets[a]) return offsets[a + 1] - offsets[a];
    return runs::row_count(runs.data() + offsets[a]);
  }
  std::size_t total() const { return in_runs ? run_entries : neighbours.size(); }
};

/// How a search writes its lists. By default row a is particle a of the tree (empty for a
/// non-target) and entries are tree indices, with separate shift codes on a periodic domain.
struct list_layout {
  /// When set, target a fills row rename[a] and neighbour b is written as rename[b] (e.g. the
  /// topology's storage indices), `rows` rows in all. The renaming must keep the targets in
  /// ascending order (rename[a] < rename[a'] for targets a < a'): chunks of consecutive
  /// targets then fill consecutive rows, and each row is written once, in place.
  const std::size_t* rename = nullptr;
  std::size_t rows = 0;
  shift_storage shifts = shift_storage::separate;
};

/// How many chunks to cut `work_items` items into for dynamic scheduling over the host threads.
inline std::size_t chunk_count_for(std::size_t work_items) {
  const std::size_t wanted = 16 * static_cast<std::size_t>(flecsi_lite::concurrency());
  return std::max<std::size_t>(1, std::min(work_items, wanted));
}

}  // namespace flecsi_lite::topology::ntree

// Lists are large: tasks take them by reference (the searches that replace them wait for every
// pending launch).
template<>
struct flecsi_lite::execution::shared_argument<flecsi_lite::topology::ntree::neighbour_lists> : std::true_type {};
