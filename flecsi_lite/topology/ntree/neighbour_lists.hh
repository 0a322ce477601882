// Vocabulary shared by the ntree neighbour searches: the pair criterion (gather or symmetric
// radius in units of h), search options, and neighbour lists in compressed sparse row form.
#pragma once

#include "flecsi_lite/topology/ntree/host_parallel.hh"
#include "flecsi_lite/topology/ntree/periodic.hh"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <cstring>
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

inline double interaction_radius(interaction kind, double support, double h_target,
                                 double h_source) {
  return kind == interaction::gather
           ? interaction_radius<interaction::gather>(support, h_target, h_source)
           : interaction_radius<interaction::symmetric>(support, h_target, h_source);
}

/// The pair criterion: strictly inside the radius.
inline bool within_radius(double distance_squared, double radius) {
  return distance_squared < radius * radius;
}

struct search_options {
  interaction kind = interaction::gather;
  /// Radius of the kernel's compact support in units of h.
  double support = 2.0;
  /// targets[i] != 0 marks particle i (sorted order) as a target; nullptr makes all targets.
  const std::uint8_t* targets = nullptr;

  bool is_target(std::size_t i) const { return targets == nullptr || targets[i] != 0; }
};

/// Neighbours of every target in compressed sparse row form: those of particle a are
/// neighbours[offsets[a] .. offsets[a + 1]), in ascending sorted index; a non-target has none.
/// With a periodic domain, shifts[j] is the image shift code of entry j (x_b + shift).
struct neighbour_lists {
  std::vector<std::size_t> offsets{0};
  std::vector<std::uint32_t> neighbours;
  std::vector<shift_code> shifts;

  std::size_t size() const { return offsets.size() - 1; }
  std::size_t count(std::size_t a) const { return offsets[a + 1] - offsets[a]; }
  std::size_t total() const { return neighbours.size(); }
};

/// Parallel assembly of neighbour_lists: the targets are cut into chunks of contiguous sorted
/// indices, each worked on by one thread that appends its entries to the chunk's own buffers and
/// writes the counts of its targets; then offsets are scanned and the buffers copied in place.
/// Buffers are kept between searches, so a steady state allocates nothing.
class neighbour_list_builder {
public:
  struct chunk {
    std::size_t first_target = 0;
    std::vector<std::uint32_t> neighbours;
    std::vector<shift_code> shifts;
  };

  /// Prepares `out` for n particles (all counts zero) and `chunk_count` empty chunks.
  void start(std::size_t n, std::size_t chunk_count, neighbour_lists& out) {
    out.offsets.assign(n + 1, 0);
    if (chunks_.size() < chunk_count) chunks_.resize(chunk_count);
    chunk_count_ = chunk_count;
    for (std::size_t c = 0; c < chunk_count; ++c) {
      chunks_[c].first_target = 0;
      chunks_[c].neighbours.clear();
      chunks_[c].shifts.clear();
    }
  }

  chunk& operator[](std::size_t c) { return chunks_[c]; }

  /// Turns the counts in out.offsets into offsets and gathers the chunks' entries.
  void finish(neighbour_lists& out, bool with_shifts) {
    const std::size_t n = out.offsets.size() - 1;
    const std::size_t total = host_exclusive_scan("ntree::neighbour_lists::offsets",
                                                  out.offsets.data(), n + 1);
    out.neighbours.resize(total);
    out.shifts.resize(with_shifts ? total : 0);
    host_for("ntree::neighbour_lists::gather", chunk_count_, [&](std::size_t c) {
      const chunk& part = chunks_[c];
      if (part.neighbours.empty()) return;
      const std::size_t at = out.offsets[part.first_target];
      std::memcpy(out.neighbours.data() + at, part.neighbours.data(),
                  part.neighbours.size() * sizeof(std::uint32_t));
      if (with_shifts)
        std::memcpy(out.shifts.data() + at, part.shifts.data(),
                    part.shifts.size() * sizeof(shift_code));
    });
  }

private:
  std::vector<chunk> chunks_;
  std::size_t chunk_count_ = 0;
};

/// How many chunks to cut `work_items` items into for dynamic scheduling over the host threads.
inline std::size_t chunk_count_for(std::size_t work_items) {
  const std::size_t wanted = 16 * static_cast<std::size_t>(host_concurrency());
  return std::max<std::size_t>(1, std::min(work_items, wanted));
}

} // namespace flecsi_lite::topology::ntree
