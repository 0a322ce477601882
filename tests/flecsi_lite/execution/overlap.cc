// Communication overlaps computation: a large ghost copy whose data is final is posted before an
// independent long task runs (eager copies), and completes while that task runs (forall polls
// MPI between chunks). Asserted from the trace's order of events, never from durations.
#include <catch2/catch.hpp>

#include "flecsi_lite/data.hh"
#include "flecsi_lite/execution.hh"
#include "flecsi_lite/runtime/context.hh"
#include "flecsi_lite/topology/narray.hh"
#include "index_values.hh"

using namespace flecsi_lite;
using testing::fill_scaled_index;
using testing::ghosts_hold;
using topology::narray;

namespace {
const field<double>::definition<narray> big{"big"};
const field<double>::definition<narray> other{"other"};

/// Long and independent of `big`: loops until no communication is in flight (bounded by a count
/// of rounds, so that without polling it ends, and the test fails, rather than hang).
int long_task(field<double>::accessor<rw> f) {
  auto& ex = execution::executor::instance();
  int rounds = 0;
  do forall(f.size(), [&](std::size_t i) { f(i) = 0.5 * f(i) + 1.0; });
  while (ex.communication_in_flight() && ++rounds < 2000);
  return rounds;
}
const execution::trace_event& find(const std::vector<execution::trace_event>& trace, const std::string& name) {
  for (const auto& e : trace)
    if (e.name == name) return e;
  FAIL("no trace event " << name);
  return trace.front();
}
}  // namespace

TEST_CASE("a ghost copy is posted when its data is ready and advances while a long task runs") {
  REQUIRE(runtime::size() > 1);  // on one rank the copy is local and never in flight
  auto& ex = execution::executor::instance();
  // 200000 ghosts per side: 1.6 MB messages, beyond any eager protocol.
  narray n(800000 * runtime::size(), 200000, true);
  execute<fill_scaled_index>(n, big(n), 1.0);
  execute<fill_scaled_index>(n, other(n), 2.0);
  execute<ghosts_hold>(n, big(n), 1.0).get();  // the ghosts of big are read: later writes copy eagerly
  wait_all();
  ex.clear_trace();
  ex.enable_tracing(true);
  execute<fill_scaled_index>(n, big(n), 3.0);  // the last writer of big: its copy is ready after it
  auto rounds = execute<long_task>(other(n));  // independent of big
  rounds.get();                                // runs before any reader of big's ghosts is recorded
  const bool delivered = execute<ghosts_hold>(n, big(n), 3.0).get();
  wait_all();
  ex.enable_tracing(false);
  const auto& trace = ex.trace();
  const auto& copy = find(trace, "ghost copy big");
  const auto& task = find(trace, "long_task");
  CHECK(copy.begin <= task.begin);  // posted before the task, not when its reader was recorded
  CHECK(copy.end > task.begin);     // in flight during the task...
  CHECK(copy.end <= task.end);      // ...and completed while it ran (polled between chunks)
  CHECK(rounds.get() < 2000);
  CHECK(delivered);  // and delivered the owners' values
}
