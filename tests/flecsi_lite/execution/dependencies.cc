// The executor derives read-after-write, write-after-read and write-after-write dependencies
// from privileges, and runs independent launches out of order while a ghost copy is in flight.
#include <catch2/catch.hpp>

#include "flecsi_lite/data.hh"
#include "flecsi_lite/execution.hh"
#include "flecsi_lite/runtime/context.hh"
#include "flecsi_lite/topology/narray.hh"

using namespace flecsi_lite;
using topology::narray;

namespace {
const field<double>::definition<narray> a{"a"};
const field<double>::definition<narray> b{"b"};

void set(field<double>::accessor<wo> f, double value) {
  for (std::size_t i = 0; i < f.size(); ++i) f(i) = value;
}
void add(field<double>::accessor<rw> f, double value) {
  for (std::size_t i = 0; i < f.size(); ++i) f(i) += value;
}
double first(field<double>::accessor<ro> f) { return f.size() ? f(0) : 0.0; }
void copy(field<double>::accessor<ro> from, field<double>::accessor<wo> to) {
  for (std::size_t i = 0; i < to.size(); ++i) to(i) = from(i);
}
double sum_with_ghosts(field<double>::accessor<ro, ro> f) {
  double s = 0;
  for (std::size_t i = 0; i < f.size(); ++i) s += f(i);
  return s;
}
void nothing() {}
double one() { return 1.0; }
double first_plus(field<double>::accessor<ro> f, double extra) { return (f.size() ? f(0) : 0.0) + extra; }

std::vector<std::string> completion_order() {
  std::vector<std::string> names;
  for (auto& e : execution::executor::instance().trace()) names.push_back(e.name);
  return names;
}
std::size_t position_of(const std::vector<std::string>& names, const std::string& name) {
  return static_cast<std::size_t>(std::find(names.begin(), names.end(), name) - names.begin());
}
}  // namespace

TEST_CASE("read after write: a reader sees the preceding write") {
  narray n(64, 1, false);
  execute<set>(a(n), 1.0);
  auto before = execute<first>(a(n));
  execute<add>(a(n), 2.0);
  auto after = execute<first>(a(n));
  CHECK(before.get() == 1.0);
  CHECK(after.get() == 3.0);
}

TEST_CASE("write after read: a later write waits for earlier readers") {
  narray n(64, 1, false);
  execute<set>(a(n), 5.0);
  execute<copy>(a(n), b(n));  // reads a
  execute<set>(a(n), 7.0);    // must not overtake the copy
  CHECK(execute<first>(b(n)).get() == 5.0);
  CHECK(execute<first>(a(n)).get() == 7.0);
}

TEST_CASE("write after write: the last write wins") {
  narray n(64, 1, false);
  execute<set>(a(n), 1.0);
  execute<add>(a(n), 1.0);
  execute<set>(a(n), 9.0);
  execute<add>(a(n), 1.0);
  CHECK(execute<first>(a(n)).get() == 10.0);
}

// The two cases above run in program order anyway. Here the earlier launch waits for a
// reduction's collective (communication, in flight for at least one scheduling round) while the
// later one is ready at once: only the dependency keeps the later one from running first.
TEST_CASE("write after read: a writer that could run first waits for a delayed reader") {
  narray n(64, 1, false);
  execute<set>(a(n), 5.0);
  wait_all();
  auto total = reduce<one, reduction::sum>();    // in flight for a while
  auto seen = execute<first_plus>(a(n), total);  // reads a, waits for the collective
  execute<set>(a(n), 7.0);                       // ready at once without the edge
  CHECK(seen.get() == 5.0 + runtime::size());
  CHECK(execute<first>(a(n)).get() == 7.0);
}

TEST_CASE("write after write: a delayed writer is not overtaken by a later one") {
  narray n(64, 1, false);
  execute<set>(a(n), 1.0);
  wait_all();
  auto total = reduce<one, reduction::sum>();
  execute<set>(a(n), total);  // the earlier writer waits for the collective
  execute<set>(a(n), 9.0);    // the later writer: its value must be the final one
  wait_all();                 // (a reader recorded now could run between the two writers)
  CHECK(execute<first>(a(n)).get() == 9.0);
}

TEST_CASE("futures are task arguments: the task waits for the value") {
  narray n(64, 1, false);
  execute<set>(a(n), 2.5);
  auto value = execute<first>(a(n));
  execute<set>(b(n), value);
  CHECK(execute<first>(b(n)).get() == 2.5);
}

TEST_CASE("independent launches run while a ghost copy is in flight") {
  auto& ex = execution::executor::instance();
  narray n(64, 2, true);
  execute<set>(a(n), 1.0);
  execute<set>(b(n), 1.0);
  wait_all();
  ex.clear_trace();
  ex.enable_tracing(true);
  execute<add>(a(n), 1.0);                  // writes a: ghosts of a become stale
  auto s = execute<sum_with_ghosts>(a(n));  // needs a ghost copy of a
  execute<add>(b(n), 1.0);                  // independent of a
  execute<nothing>();
  CHECK(s.get() == 2.0 * (n.owned_size() + n.ghost_size()));
  wait_all();
  ex.enable_tracing(false);
  const auto order = completion_order();
  REQUIRE(order.size() == 5);
  CHECK(order[0] == "add");
  CHECK(position_of(order, "ghost copy a") < position_of(order, "sum_with_ghosts"));
  if (runtime::size() > 1) {
    // The copy waits for messages, so the later independent launches complete first.
    CHECK(position_of(order, "nothing") < position_of(order, "sum_with_ghosts"));
  } else {
    // One rank copies its own periodic images at once: program order.
    CHECK(order == std::vector<std::string>{"add", "ghost copy a", "sum_with_ghosts", "add", "nothing"});
  }
  // Sequence numbers record program order whatever the completion order.
  for (auto& e : ex.trace())
    if (e.name == "nothing") CHECK(e.sequence > ex.trace()[0].sequence);
}
