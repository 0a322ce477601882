// Builds a ghost plan from what each rank needs: for every ghost slot, the rank that owns the
// entity and the entity's global id. The requests are exchanged (all-to-all) so that every owner
// learns which of its entities are SHARED with whom, and in which order to send them.
#pragma once

#include "flecsi_lite/data/ghost_plan.hh"

#include <mpi.h>

#include <cstdint>
#include <functional>
#include <vector>

namespace flecsi_lite::data {

/// ghost_owner[k] and ghost_id[k] describe ghost slot k; slots of one owner must be contiguous.
/// owned_index_of(id) gives the owned index of an entity this rank owns (called for each entity
/// another rank requests). Collective over `comm`.
ghost_plan build_ghost_plan(const std::vector<int>& ghost_owner, const std::vector<std::uint64_t>& ghost_id,
                            const std::function<std::size_t(std::uint64_t)>& owned_index_of, MPI_Comm comm);

}  // namespace flecsi_lite::data
