// The loop vocabulary (execution/forall.hh): every index visited once under both schedules,
// reductions equal to the serial ones, the exclusive scan equal to the serial prefix sum.
#include <catch2/catch.hpp>

#include "flecsi_lite/execution.hh"

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <vector>

using flecsi_lite::dynamic_schedule;

TEST_CASE("forall visits every index once, evenly split or dynamically scheduled") {
  for (std::size_t n : {std::size_t{0}, std::size_t{1}, std::size_t{1000}, std::size_t{4099}}) {
    std::vector<int> even(n, 0), dynamic(n, 0), chunked(n, 0);
    flecsi_lite::forall(
      n, [&](std::size_t i) { ++even[i]; }, "test::even");
    flecsi_lite::forall(
      n, [&](std::size_t i) { ++dynamic[i]; }, "test::dynamic", dynamic_schedule{});
    flecsi_lite::forall(
      n, [&](std::size_t i) { ++chunked[i]; }, "test::chunked", dynamic_schedule{7});
    CHECK(std::all_of(even.begin(), even.end(), [](int c) { return c == 1; }));
    CHECK(std::all_of(dynamic.begin(), dynamic.end(), [](int c) { return c == 1; }));
    CHECK(std::all_of(chunked.begin(), chunked.end(), [](int c) { return c == 1; }));
  }
}

TEST_CASE("forall_reduce gives the serial minimum, maximum and integer sum under both schedules") {
  const std::size_t n = 5003;
  std::vector<double> x(n);
  for (std::size_t i = 0; i < n; ++i) x[i] = double((i * 7919) % 1009) - 500.5;
  double top = 0, bottom = 0, top_dynamic = 0;
  std::int64_t sum = 0;
  flecsi_lite::forall_reduce(
    n, [&](std::size_t i, double& m) { m = std::max(m, x[i]); }, Kokkos::Max<double>(top), "test::max");
  flecsi_lite::forall_reduce(
    n, [&](std::size_t i, double& m) { m = std::min(m, x[i]); }, Kokkos::Min<double>(bottom), "test::min",
    dynamic_schedule{256});
  flecsi_lite::forall_reduce(
    n, [&](std::size_t i, double& m) { m = std::max(m, x[i]); }, Kokkos::Max<double>(top_dynamic), "test::max_dynamic",
    dynamic_schedule{});
  flecsi_lite::forall_reduce(
    n, [&](std::size_t i, std::int64_t& s) { s += static_cast<std::int64_t>(i); }, Kokkos::Sum<std::int64_t>(sum),
    "test::sum");
  CHECK(top == *std::max_element(x.begin(), x.end()));
  CHECK(top_dynamic == top);
  CHECK(bottom == *std::min_element(x.begin(), x.end()));
  CHECK(sum == static_cast<std::int64_t>(n * (n - 1) / 2));
}

TEST_CASE("exclusive_scan is the serial exclusive prefix sum and returns the total") {
  const std::size_t n = 3001;
  std::vector<std::size_t> counts(n), expected(n);
  for (std::size_t i = 0; i < n; ++i) counts[i] = (i * 31) % 17;
  std::exclusive_scan(counts.begin(), counts.end(), expected.begin(), std::size_t{0});
  const std::size_t total = std::accumulate(counts.begin(), counts.end(), std::size_t{0});
  CHECK(flecsi_lite::exclusive_scan(counts.data(), n, "test::scan") == total);
  CHECK(counts == expected);
  std::size_t nothing = 0;
  CHECK(flecsi_lite::exclusive_scan(&nothing, 0) == 0);
}
