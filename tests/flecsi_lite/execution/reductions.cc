// reduce<task, op>: sum, min, max over ranks, identical on every rank; exact_sum identical on
// every rank count.
#include <catch2/catch.hpp>

#include "flecsi_lite/data.hh"
#include "flecsi_lite/execution.hh"
#include "flecsi_lite/runtime/context.hh"
#include "flecsi_lite/topology/narray.hh"

using namespace flecsi_lite;
using topology::narray;

namespace {
const field<double>::definition<narray> value{"value"};

double rank_value() { return static_cast<double>(runtime::rank() + 1); }
long rank_count() { return 1; }
// Values whose naive sum depends on the grouping: 1e16, 1, -1e16, 1, ... over 64 entities.
void fill(const narray& n, field<double>::accessor<wo> f) {
  for (std::size_t i = 0; i < f.size(); ++i)
    f(i) = n.global_index(i) % 2 ? 1.0 : (n.global_index(i) % 4 ? -1e16 : 1e16);
}
util::exact_sum local_exact(field<double>::accessor<ro> f) {
  util::exact_sum s;
  for (std::size_t i = 0; i < f.size(); ++i) s.add(f(i));
  return s;
}
double local_plain(field<double>::accessor<ro> f) {
  double s = 0;
  for (std::size_t i = 0; i < f.size(); ++i) s += f(i);
  return s;
}
double twice(double x) { return 2 * x; }
// Rank r's value: 1, 1e16, -1e16, 1, 1, 1e16, ... Summed left to right in rank order (1 + 1e16
// rounds to 1e16) 4 ranks give 1, pairwise ((v0 + v1) + (v2 + v3)) 0.
double order_sensitive(int r) {
  const double values[4] = {1.0, 1e16, -1e16, 1.0};
  return values[r % 4];
}
double my_order_sensitive() { return order_sensitive(runtime::rank()); }
double one_after(double) { return 1.0; }
double local_plain_with_ghosts(field<double>::accessor<ro, ro> f) {
  double s = 0;
  for (std::size_t i = 0; i < f.size(); ++i) s += f(i);
  return s;
}
double thousand_times_rank() { return 1000.0 * (runtime::rank() + 1); }
}  // namespace

TEST_CASE("sum, min and max over ranks") {
  const int p = runtime::size();
  CHECK(reduce<rank_value, reduction::sum>().get() == p * (p + 1) / 2.0);
  CHECK(reduce<rank_value, reduction::min>().get() == 1.0);
  CHECK(reduce<rank_value, reduction::max>().get() == double(p));
  CHECK(reduce<rank_count, reduction::sum>().get() == p);
}

TEST_CASE("exact sums are the same on any number of ranks") {
  narray n(64, 0, false);
  execute<fill>(n, value(n));
  CHECK(reduce<local_exact, reduction::exact_sum>(value(n)).get() == 32.0);
  // The same partial sums, each already rounded on its rank, still combine exactly.
  const double combined = reduce<local_plain, reduction::exact_sum>(value(n)).get();
  const double identical_everywhere = reduce<local_plain, reduction::sum>(value(n)).get();
  double lo = combined, hi = combined;
  MPI_Allreduce(MPI_IN_PLACE, &lo, 1, MPI_DOUBLE, MPI_MIN, runtime::communicator());
  MPI_Allreduce(MPI_IN_PLACE, &hi, 1, MPI_DOUBLE, MPI_MAX, runtime::communicator());
  CHECK(lo == hi);
  (void)identical_everywhere;
}

TEST_CASE("a reduction's future feeds a task") {
  auto total = reduce<rank_value, reduction::sum>();
  auto doubled = execute<twice>(total);
  const int p = runtime::size();
  CHECK(doubled.get() == p * (p + 1.0));
}

TEST_CASE("a sum over ranks adds in rank order (the documented canonical order)") {
  const int p = runtime::size();
  double expected = order_sensitive(0);
  for (int r = 1; r < p; ++r) expected += order_sensitive(r);
  const double combined = reduce<my_order_sensitive, reduction::sum>().get();
  CHECK(combined == expected);  // bitwise: the same rounding steps
  double lo = combined, hi = combined;
  MPI_Allreduce(MPI_IN_PLACE, &lo, 1, MPI_DOUBLE, MPI_MIN, runtime::communicator());
  MPI_Allreduce(MPI_IN_PLACE, &hi, 1, MPI_DOUBLE, MPI_MAX, runtime::communicator());
  CHECK(lo == hi);
}

// Collectives match by the order each rank starts them. On rank 0 the first reduction's local
// part waits for a future the other ranks do not pass (a task behind a ghost copy), while the
// second's is ready at once: started as they become ready, rank 0 would start the second
// collective while the others start the first, and the values would cross.
TEST_CASE("reductions start their collectives in program order on every rank") {
  narray n(64, 2, true);
  execute<fill>(n, value(n));
  auto delayed = execute<local_plain_with_ghosts>(value(n));  // waits for a ghost copy
  auto first =
    runtime::rank() == 0 ? reduce<one_after, reduction::sum>(delayed) : reduce<one_after, reduction::sum>(0.0);
  auto second = reduce<thousand_times_rank, reduction::sum>();
  const int p = runtime::size();
  CHECK(second.get() == 1000.0 * p * (p + 1) / 2);
  CHECK(first.get() == p);
}
