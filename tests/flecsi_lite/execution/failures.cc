// A task's exception reaches the future of the task that threw, not an unrelated one; launches
// that depend on it are cancelled (never run) and their futures name the failure; wait_all()
// reports a failure no future reported. Every rank fails alike here (SPMD), so the run goes on.
#include <catch2/catch.hpp>

#include "flecsi_lite/data.hh"
#include "flecsi_lite/execution.hh"
#include "flecsi_lite/topology/narray.hh"

#include <stdexcept>

using namespace flecsi_lite;
using topology::narray;

namespace {
const field<double>::definition<narray> a{"a"};
const field<double>::definition<narray> b{"b"};
int dependents_run = 0;

void set(field<double>::accessor<wo> f, double v) {
  for (std::size_t i = 0; i < f.size(); ++i) f(i) = v;
}
void explode(field<double>::accessor<rw> f) {
  f(0) = -1;
  throw std::runtime_error("the explosion");
}
double first_with_ghosts(field<double>::accessor<ro, ro> f) {
  ++dependents_run;
  return f(0);
}
double first(field<double>::accessor<ro> f) { return f(0); }
double twice(double x) {
  ++dependents_run;
  return 2 * x;
}
double local_first(field<double>::accessor<ro> f) {
  ++dependents_run;
  return f(0);
}
}  // namespace

TEST_CASE("an exception reaches its own future and cancels the dependents") {
  auto& ex = execution::executor::instance();
  narray n(32, 1, true);
  execute<set>(a(n), 1.0);
  execute<set>(b(n), 2.0);
  dependents_run = 0;
  auto failed = execute<explode>(a(n));
  auto reader = execute<first_with_ghosts>(a(n));            // depends through the ghost copy
  auto reduced = reduce<local_first, reduction::sum>(a(n));  // a reduction depending on it
  auto chained = execute<twice>(reader);                     // depends through a future
  auto unrelated = execute<first>(b(n));
  CHECK(unrelated.get() == 2.0);  // not the failure's business
  CHECK_THROWS_WITH(failed.get(), "the explosion");
  CHECK_THROWS_WITH(reader.get(), Catch::Contains("cancelled because 'explode' failed: the explosion"));
  CHECK_THROWS_WITH(reduced.get(), Catch::Contains("cancelled because 'explode' failed"));
  CHECK_THROWS_WITH(chained.get(), Catch::Contains("cancelled because 'explode' failed"));
  CHECK(dependents_run == 0);
  wait_all();  // every failure was reported through a future: nothing more to say
  ex.forgive_failures();
  // The fields still work: a new writer runs and its readers see it.
  execute<set>(a(n), 4.0);
  CHECK(execute<first_with_ghosts>(a(n)).get() == 4.0);
}

TEST_CASE("wait_all reports a failure that no future reported") {
  narray n(16, 1, false);
  execute<set>(a(n), 1.0);
  execute<explode>(a(n));
  CHECK_THROWS_WITH(wait_all(), "the explosion");
  wait_all();  // reported once
  execution::executor::instance().forgive_failures();
}
