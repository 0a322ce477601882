// Data-parallel loops over entities inside tasks, on the framework's Kokkos execution space.
#pragma once

#include "flecsi_lite/util/kokkos.hh"

namespace flecsi_lite {

template<class Body>
void forall(std::size_t n, const Body& body, const char* name = "flecsi_lite::forall") {
  Kokkos::parallel_for(name, Kokkos::RangePolicy<execution_space>(0, n), body);
}

template<class Reducer, class Body>
void forall_reduce(std::size_t n, const Body& body, Reducer reducer,
                   const char* name = "flecsi_lite::forall_reduce") {
  Kokkos::parallel_reduce(name, Kokkos::RangePolicy<execution_space>(0, n), body, reducer);
}

} // namespace flecsi_lite
