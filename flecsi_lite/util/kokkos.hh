// The Kokkos spaces the framework stores fields in and runs tasks on. Fields live in host memory
// (MPI and the tree code touch them directly); a device port changes these two lines and adds
// mirrors in the ghost-copy engine.
#pragma once

#include <Kokkos_Core.hpp>

namespace flecsi_lite {
using execution_space = Kokkos::DefaultHostExecutionSpace;
using memory_space = execution_space::memory_space;
}  // namespace flecsi_lite
