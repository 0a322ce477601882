// Test tasks on the narray: fill a field with scale * global index, and check that its ghosts
// hold the owners' values (what a correct ghost copy delivers); and whether a check holds on
// every rank.
#pragma once

#include "flecsi_lite/data.hh"
#include "flecsi_lite/execution.hh"
#include "flecsi_lite/runtime/context.hh"
#include "flecsi_lite/topology/narray.hh"

namespace flecsi_lite::testing {

inline void fill_scaled_index(const topology::narray& n, field<double>::accessor<wo> f, double scale) {
  forall(f.size(), [&](std::size_t i) { f(i) = scale * static_cast<double>(n.global_index(i)); });
}

inline bool ghosts_hold(const topology::narray& n, field<double>::accessor<ro, ro> f, double scale) {
  for (std::size_t i = f.owned_size(); i < f.size(); ++i)
    if (f(i) != scale * static_cast<double>(n.global_index(i))) return false;
  return true;
}

/// Collective: whether `mine` is true on every rank.
inline bool all_ranks(bool mine) {
  int in = mine, out = 0;
  MPI_Allreduce(&in, &out, 1, MPI_INT, MPI_LAND, runtime::communicator());
  return out != 0;
}

}  // namespace flecsi_lite::testing
