// What one call of ntree::distribute() did: balance of particles and work over the ranks, the
// EXCLUSIVE / SHARED / GHOST classification of this rank's particles, traffic and phase times.
#pragma once

#include <cstddef>
#include <cstdint>

namespace flecsi_lite::topology::ntree {

struct distribution_stats {
  // Over all ranks (the same on every rank).
  std::uint64_t global_count = 0;
  std::size_t owned_min = 0, owned_max = 0;
  double owned_mean = 0;
  double count_imbalance = 1;  ///< max / mean of owned particles per rank
  double work_total = 0;       ///< sum of the balancing weights (the particle count without one)
  double work_max = 0, work_mean = 0;
  double work_imbalance = 1;  ///< max / mean of the summed weights per rank
  std::uint64_t moved = 0;    ///< particles that changed rank
  std::uint64_t ghost_total = 0;

  // This rank.
  std::size_t owned = 0;
  std::size_t exclusive = 0;           ///< owned, needed by no other rank
  std::size_t shared = 0;              ///< owned, sent to at least one other rank
  std::size_t ghosts = 0;              ///< copies of other ranks' particles held here
  std::size_t sent_away = 0;           ///< particles this rank sent to other ranks in the sort
  std::size_t branches = 0;            ///< top branches this rank shared
  std::size_t bytes_per_particle = 0;  ///< bytes moved per particle (all fields)
  double work = 0;                     ///< summed weights of the owned particles

  // Phase times on this rank, seconds.
  double time_keys = 0;        ///< bounding box and keys
  double time_splitters = 0;   ///< local order, samples, splitters
  double time_exchange = 0;    ///< all-to-all of all fields
  double time_local_sort = 0;  ///< sort of the received particles
  double time_branches = 0;    ///< owned tree, branch sharing, shared particles
  double time_ghosts = 0;      ///< ghost plan
  double time_tree = 0;        ///< ghost copies of the built-in fields, local tree over owned and ghosts
  double time_total = 0;
};

}  // namespace flecsi_lite::topology::ntree
