// Vocabulary shared by the ntree neighbour searches: the pair criterion (gather or symmetric
// radius in units of h), search options, and neighbour lists in compressed sparse row form with
// their layouts (image shift codes separate or packed into the entries, renamed rows).
#pragma once

#include "flecsi_lite/execution/forall.hh"
#include "flecsi_lite/execution/shared_argument.hh"
#include "flecsi_lite/topology/ntree/periodic.hh"

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
///             particles in the tree.
enum class shift_storage { separate, packed };

inline constexpr int packed_index_bits = 27;
inline constexpr std::uint32_t packed_index_mask = (std::uint32_t{1} << packed_index_bits) - 1;
static_assert(shift_code_count<3> <= (1 << (32 - packed_index_bits)), "shift codes must fit the top bits");

/// A packed entry: neighbour b (< 2^27) and its shift code.
inline std::uint32_t packed_entry(std::uint32_t b, shift_code code) {
  return b | static_cast<std::uint32_t>(code) << packed_index_bits;
}
inline std::uint32_t packed_neighbour(std::uint32_t entry) { return entry & packed_index_mask; }
inline shift_code packed_shift(std::uint32_t entry) { return static_cast<shift_code>(entry >> packed_index_bits); }

/// Neighbours of every target in compressed sparse row form: those of particle a are
/// neighbours[offsets[a] .. offsets[a + 1]), in ascending sorted index; a non-target has none.
/// With a periodic domain, shifts[j] is the image shift code of entry j (x_b + shift), unless
/// the codes are packed into the entries (shift_storage::packed).
struct neighbour_lists {
  std::vector<std::size_t> offsets{0};
  std::vector<std::uint32_t> neighbours;
  std::vector<shift_code> shifts;

  std::size_t size() const { return offsets.size() - 1; }
  std::size_t count(std::size_t a) const { return offsets[a + 1] - offsets[a]; }
  std::size_t total() const { return neighbours.size(); }
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
