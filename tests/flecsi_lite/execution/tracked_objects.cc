// Tracked objects (data/tracked.hh): the executor orders the tasks that use one by their
// privileges, as for a field's owned region. On 2 ranks a writer that waits for a ghost copy lets
// independent launches run first, so the tests below fail if the object's accesses were ignored.
#include <catch2/catch.hpp>

#include "flecsi_lite/data.hh"
#include "flecsi_lite/execution.hh"
#include "flecsi_lite/runtime/context.hh"
#include "flecsi_lite/topology/narray.hh"

#include <type_traits>

using namespace flecsi_lite;
using topology::narray;

namespace {
const field<double>::definition<narray> a{"a"};

struct tally {
  double value = 0;
};

void set(field<double>::accessor<wo> f, double value) {
  for (std::size_t i = 0; i < f.size(); ++i) f(i) = value;
}
// Waits for the ghost copy of a: the executor runs later independent launches meanwhile.
void store_sum(field<double>::accessor<ro, ro> f, tracked<tally>::accessor<wo> out) {
  double s = 0;
  for (std::size_t i = 0; i < f.size(); ++i) s += f(i);
  out->value = s;
}
double read(tracked<tally>::accessor<ro> in) { return in->value; }
double read_with_ghosts(tracked<tally>::accessor<ro> in, field<double>::accessor<ro, ro> f) {
  return in->value + 0 * f(f.size() - 1);
}
void overwrite(tracked<tally>::accessor<wo> out, double value) { out->value = value; }

std::size_t position_of(const std::string& name) {
  const auto& trace = execution::executor::instance().trace();
  for (std::size_t i = 0; i < trace.size(); ++i)
    if (trace[i].name == name) return i;
  return trace.size();
}

// a holds 1 everywhere, then its owned values change to 2 with stale ghosts: the next reader of
// its ghosts waits for a copy.
void make_ghosts_stale(narray& n) {
  execute<set>(a(n), 1.0);
  wait_all();
  execute<set>(a(n), 2.0);
}
}  // namespace

// Read-only access is const: writing through it does not compile.
static_assert(std::is_same_v<decltype(*std::declval<tracked<tally>::accessor<ro>>()), const tally&>);
static_assert(std::is_same_v<decltype(*std::declval<tracked<tally>::accessor<rw>>()), tally&>);
static_assert(!std::is_assignable_v<decltype((std::declval<tracked<tally>::accessor<ro>>()->value)), double>);

TEST_CASE("read after write: a reader of a tracked object sees the writer's value") {
  auto& ex = execution::executor::instance();
  narray n(64, 2, true);
  tracked<tally> total{"total"};
  make_ghosts_stale(n);
  ex.clear_trace();
  ex.enable_tracing(true);
  execute<store_sum>(a(n), total);   // waits for the ghost copy
  auto seen = execute<read>(total);  // no field: only the object orders it
  CHECK(seen.get() == 2.0 * (n.owned_size() + n.ghost_size()));
  wait_all();
  ex.enable_tracing(false);
  CHECK(position_of("store_sum") < position_of("read"));
}

TEST_CASE("write after read: a writer of a tracked object waits for its earlier readers") {
  narray n(64, 2, true);
  tracked<tally> total{"total"};
  execute<overwrite>(total, 5.0);
  make_ghosts_stale(n);
  auto seen = execute<read_with_ghosts>(total, a(n));  // waits for the ghost copy
  execute<overwrite>(total, 7.0);                      // must not overtake it
  CHECK(seen.get() == 5.0);
  CHECK(execute<read>(total).get() == 7.0);
}

TEST_CASE("write after write and host access: the last writer's value, after pending tasks") {
  narray n(64, 2, true);
  tracked<tally> total{"total"};
  make_ghosts_stale(n);
  execute<store_sum>(a(n), total);  // waits for the ghost copy
  execute<overwrite>(total, 3.0);   // must not run before it
  CHECK(total.host().value == 3.0);
  CHECK(execution::executor::instance().pending() == 0);
}
