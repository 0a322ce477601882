// Ghost plans built from the sender's side: the owner decides which of its particles another rank
// needs (branch sharing), so the plan is built from send lists; the receiver learns only counts
// (one MPI_Alltoall). Values travel along the plan by the executor's ghost copies.
#pragma once

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

}  // namespace flecsi_lite::topology::ntree
