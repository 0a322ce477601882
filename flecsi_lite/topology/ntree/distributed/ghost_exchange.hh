// Ghost plans built from the sender's side and a blocking copy of field values along a plan.
// The owner decides which of its particles another rank needs (branch sharing), so the plan is
// built from send lists; the receiver learns only counts (one MPI_Alltoall).
#pragma once

#include "flecsi_lite/data/field_storage.hh"
#include "flecsi_lite/data/ghost_plan.hh"

#include <mpi.h>

#include <cstddef>
#include <vector>

namespace flecsi_lite::topology::ntree {

/// Collective: the plan in which this rank sends owned indices send_to[r] (in that order) to
/// every rank r (send_to has one list per rank). Ghost slots are filled source rank after
/// source rank, each block in the sender's order.
data::ghost_plan build_sender_plan(std::vector<std::vector<std::size_t>> send_to, MPI_Comm comm);

/// Number of ghost slots the plan fills.
std::size_t ghost_count(const data::ghost_plan& plan);

/// Collective: copies the values of every storage in `fields` from the owners' SHARED entities
/// to the GHOST slots of `plan` (the ghost region starts at `owned_size`), with one
/// MPI_Alltoallv for all fields together.
void copy_to_ghosts(const data::ghost_plan& plan, const std::vector<data::field_storage_base*>& fields,
                    std::size_t owned_size, MPI_Comm comm);

} // namespace flecsi_lite::topology::ntree
