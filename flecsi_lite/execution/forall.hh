// Data-parallel loops over entities, on the framework's Kokkos execution space: the one loop
// vocabulary of tasks, topologies and specializations (Kokkos parallel_for / parallel_reduce /
// parallel_scan with a signed 64-bit index, each finished when the call returns).
// While communication is in flight, long loops run in chunks of `poll_chunk` indices and call
// the executor's poll between them, so MPI messages advance while tasks compute (MPI is
// initialised FUNNELED: only this thread may call it, and no core is spent on a progress thread).
//
//   forall(n, [&](std::size_t i) { y[i] = a * x[i]; }, "axpy");                 // even split
//   forall(n, body, "tree walk", dynamic_schedule{});                           // uneven work
//   forall_reduce(n, [&](std::size_t i, double& m) { m = std::max(m, x[i]); }, Kokkos::Max<double>(top), "max");
//   const double top = forall_max(n, [&](std::size_t i) { return x[i]; }, 0.0, "max");  // the same, from 0
//   const std::size_t total = exclusive_scan(counts, n + 1, "offsets");          // in place
#pragma once

#include "flecsi_lite/util/kokkos.hh"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <type_traits>

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
/// Set by the executor: completes finished requests, posts ready copies; true while any
/// communication is still in flight (keep polling).
inline bool (*poll_hook)() = nullptr;
/// Indices between two polls: small enough that a message waits at most a fraction of a task,
/// large enough that a chunk's parallel launch costs little against its work.
constexpr std::int64_t poll_chunk = 2048;

/// run(begin, end) over [0, n): in one call, or in chunks with polls between while
/// communication is in flight. Each index runs once, with the same arithmetic.
template<class Run>
void run_polling(std::int64_t n, const Run& run) {
  std::int64_t done = 0;
  while (n - done > poll_chunk && poll_hook && poll_hook()) {
    run(done, done + poll_chunk);
    done += poll_chunk;
  }
  if (done < n) run(done, n);
  if (done > 0 && poll_hook) poll_hook();
}

/// Reducers whose result does not depend on how the range is split (chunks may be combined).
template<class Reducer>
struct splittable : std::false_type {};
template<class T, class S>
struct splittable<Kokkos::Min<T, S>> : std::true_type {};
template<class T, class S>
struct splittable<Kokkos::Max<T, S>> : std::true_type {};

using loop_index = Kokkos::IndexType<std::int64_t>;
using even_policy = Kokkos::RangePolicy<execution_space, loop_index>;
using dynamic_policy = Kokkos::RangePolicy<execution_space, Kokkos::Schedule<Kokkos::Dynamic>, loop_index>;

inline dynamic_policy make_policy(std::int64_t begin, std::int64_t end, dynamic_schedule schedule) {
  dynamic_policy policy(begin, end);
  if (schedule.chunk > 0) policy.set_chunk_size(static_cast<int>(schedule.chunk));
  return policy;
}

/// run(begin, end, reducer) over [0, n): chunked with polls only for min/max (a sum's rounding
/// would depend on the split), the chunks' results joined in order.
template<class Reducer, class Run>
void reduce_polling(std::size_t n, Reducer reducer, const Run& run) {
  const auto count = static_cast<std::int64_t>(n);
  if constexpr (splittable<Reducer>::value) {
    typename Reducer::value_type total;
    reducer.init(total);
    run_polling(count, [&](std::int64_t begin, std::int64_t end) {
      typename Reducer::value_type part;
      run(begin, end, Reducer(part));
      reducer.join(total, part);
    });
    reducer.reference() = total;
  } else {
    run(0, count, reducer);
  }
}
}  // namespace detail

/// body(i) for i in [0, n), the range split evenly among the threads.
template<class Body>
void forall(std::size_t n, const Body& body, const char* name = "flecsi_lite::forall") {
  if (n == 0) return;
  detail::run_polling(static_cast<std::int64_t>(n), [&](std::int64_t begin, std::int64_t end) {
    Kokkos::parallel_for(name, detail::even_policy(begin, end),
                         [&body](std::int64_t i) { body(static_cast<std::size_t>(i)); });
    execution_space().fence();
  });
}

/// body(i) for i in [0, n), dynamically scheduled.
template<class Body>
void forall(std::size_t n, const Body& body, const char* name, dynamic_schedule schedule) {
  if (n == 0) return;
  detail::run_polling(static_cast<std::int64_t>(n), [&](std::int64_t begin, std::int64_t end) {
    Kokkos::parallel_for(name, detail::make_policy(begin, end, schedule),
                         [&body](std::int64_t i) { body(static_cast<std::size_t>(i)); });
    execution_space().fence();
  });
}

/// body(i, partial) for i in [0, n), combined into `reducer` (Kokkos::Sum, Min, Max, ...).
template<class Reducer, class Body>
void forall_reduce(std::size_t n, const Body& body, Reducer reducer, const char* name = "flecsi_lite::forall_reduce") {
  detail::reduce_polling(n, reducer, [&](std::int64_t begin, std::int64_t end, Reducer part) {
    Kokkos::parallel_reduce(
      name, detail::even_policy(begin, end),
      [&body](std::int64_t i, typename Reducer::value_type& partial) { body(static_cast<std::size_t>(i), partial); },
      part);
  });
}

/// The same, dynamically scheduled (for min/max reductions: the result does not depend on the
/// schedule; a floating-point sum would).
template<class Reducer, class Body>
void forall_reduce(std::size_t n, const Body& body, Reducer reducer, const char* name, dynamic_schedule schedule) {
  detail::reduce_polling(n, reducer, [&](std::int64_t begin, std::int64_t end, Reducer part) {
    Kokkos::parallel_reduce(
      name, detail::make_policy(begin, end, schedule),
      [&body](std::int64_t i, typename Reducer::value_type& partial) { body(static_cast<std::size_t>(i), partial); },
      part);
  });
}

/// The largest of `floor` and value(i) for i in [0, n), in parallel: a maximum, so the same in
/// any order (`floor` when n = 0; Kokkos' Max alone would start at the lowest double).
template<class Value>
double forall_max(std::size_t n, const Value& value, double floor, const char* name = "flecsi_lite::forall_max") {
  double top = floor;
  forall_reduce(
    n, [&value](std::size_t i, double& m) { m = std::max(m, value(i)); }, Kokkos::Max<double>(top), name);
  return std::max(floor, top);
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

}  // namespace flecsi_lite
