// Host data-parallel loops for the ntree topology: thin wrappers over Kokkos::parallel_for and
// parallel_scan on Kokkos::DefaultHostExecutionSpace with a signed 64-bit index.
#pragma once

#include <Kokkos_Core.hpp>

#include <cstddef>
#include <cstdint>

namespace flecsi_lite::topology::ntree {

using host_space = Kokkos::DefaultHostExecutionSpace;

/// Number of threads the host execution space runs.
inline int host_concurrency() { return host_space().concurrency(); }

/// body(i) for i in [0, n), statically scheduled (equal work per index).
template<class F>
void host_for(const char* label, std::size_t n, const F& body) {
  if (n == 0) return;
  Kokkos::parallel_for(
    label,
    Kokkos::RangePolicy<host_space, Kokkos::IndexType<std::int64_t>>(0,
                                                                     static_cast<std::int64_t>(n)),
    [&body](std::int64_t i) { body(static_cast<std::size_t>(i)); });
  host_space().fence();
}

/// body(i) for i in [0, n), dynamically scheduled (uneven work per index, e.g. tree walks).
template<class F>
void host_for_dynamic(const char* label, std::size_t n, const F& body) {
  if (n == 0) return;
  using policy =
    Kokkos::RangePolicy<host_space, Kokkos::Schedule<Kokkos::Dynamic>, Kokkos::IndexType<std::int64_t>>;
  Kokkos::parallel_for(label, policy(0, static_cast<std::int64_t>(n)),
                       [&body](std::int64_t i) { body(static_cast<std::size_t>(i)); });
  host_space().fence();
}

/// In-place exclusive prefix sum of values[0, n); returns the total.
template<class T>
T host_exclusive_scan(const char* label, T* values, std::size_t n) {
  T total = 0;
  if (n == 0) return total;
  Kokkos::parallel_scan(
    label,
    Kokkos::RangePolicy<host_space, Kokkos::IndexType<std::int64_t>>(0,
                                                                     static_cast<std::int64_t>(n)),
    [values](std::int64_t i, T& partial, bool final) {
      const T value = values[i];
      if (final) values[i] = partial;
      partial += value;
    },
    total);
  host_space().fence();
  return total;
}

} // namespace flecsi_lite::topology::ntree
