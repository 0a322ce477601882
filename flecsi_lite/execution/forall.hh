// Data-parallel loops over entities, on the framework's Kokkos execution space: the one loop
// vocabulary of tasks, topologies and specializations (Kokkos parallel_for / parallel_reduce /
// parallel_scan with a signed 64-bit index, each finished when the call returns).
//
//   forall(n, [&](std::size_t i) { y[i] = a * x[i]; }, "axpy");                 // even split
//   forall(n, body, "tree walk", dynamic_schedule{});                           // uneven work
//   forall_reduce(n, [&](std::size_t i, double& m) { m = std::max(m, x[i]); }, Kokkos::Max<double>(top), "max");
//   const std::size_t total = exclusive_scan(counts, n + 1, "offsets");          // in place
#pragma once

#include "flecsi_lite/util/kokkos.hh"

#include <cstddef>
#include <cstdint>

namespace flecsi_lite {

/// Iterations handed to the threads on demand, `chunk` at a time (0: Kokkos' default), for
/// loops whose work per index varies (tree walks, neighbour sums); the default schedule splits
/// the range evenly. Either way, each index's own arithmetic is the same.
struct dynamic_schedule {
  std::size_t chunk = 0;
};

/// Threads the execution space runs.
inline int concurrency() { return execution_space().concurrency(); }

namespace detail {
using loop_index = Kokkos::IndexType<std::int64_t>;
using even_policy = Kokkos::RangePolicy<execution_space, loop_index>;
using dynamic_policy = Kokkos::RangePolicy<execution_space, Kokkos::Schedule<Kokkos::Dynamic>, loop_index>;

inline dynamic_policy make_policy(std::size_t n, dynamic_schedule schedule) {
  dynamic_policy policy(0, static_cast<std::int64_t>(n));
  if (schedule.chunk > 0) policy.set_chunk_size(static_cast<int>(schedule.chunk));
  return policy;
}
} // namespace detail

/// body(i) for i in [0, n), the range split evenly among the threads.
template<class Body>
void forall(std::size_t n, const Body& body, const char* name = "flecsi_lite::forall") {
  if (n == 0) return;
  Kokkos::parallel_for(name, detail::even_policy(0, static_cast<std::int64_t>(n)),
                       [&body](std::int64_t i) { body(static_cast<std::size_t>(i)); });
  execution_space().fence();
}

/// body(i) for i in [0, n), dynamically scheduled.
template<class Body>
void forall(std::size_t n, const Body& body, const char* name, dynamic_schedule schedule) {
  if (n == 0) return;
  Kokkos::parallel_for(name, detail::make_policy(n, schedule),
                       [&body](std::int64_t i) { body(static_cast<std::size_t>(i)); });
  execution_space().fence();
}

/// body(i, partial) for i in [0, n), combined into `reducer` (Kokkos::Sum, Min, Max, ...).
template<class Reducer, class Body>
void forall_reduce(std::size_t n, const Body& body, Reducer reducer,
                   const char* name = "flecsi_lite::forall_reduce") {
  Kokkos::parallel_reduce(name, detail::even_policy(0, static_cast<std::int64_t>(n)),
                          [&body](std::int64_t i, typename Reducer::value_type& partial) {
                            body(static_cast<std::size_t>(i), partial);
                          },
                          reducer);
}

/// The same, dynamically scheduled (for min/max reductions: the result does not depend on the
/// schedule; a floating-point sum would).
template<class Reducer, class Body>
void forall_reduce(std::size_t n, const Body& body, Reducer reducer, const char* name, dynamic_schedule schedule) {
  Kokkos::parallel_reduce(name, detail::make_policy(n, schedule),
                          [&body](std::int64_t i, typename Reducer::value_type& partial) {
                            body(static_cast<std::size_t>(i), partial);
                          },
                          reducer);
}

/// In-place exclusive prefix sum of values[0, n); returns the total.
template<class T>
T exclusive_scan(T* values, std::size_t n, const char* name = "flecsi_lite::exclusive_scan") {
  T total = 0;
  if (n == 0) return total;
  Kokkos::parallel_scan(
    name, detail::even_policy(0, static_cast<std::int64_t>(n)),
    [values](std::int64_t i, T& partial, bool final) {
      const T value = values[i];
      if (final) values[i] = partial;
      partial += value;
    },
    total);
  execution_space().fence();
  return total;
}

} // namespace flecsi_lite
