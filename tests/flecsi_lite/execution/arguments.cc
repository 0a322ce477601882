// Task arguments are captured at launch: values and const references are copied when
// execute() is called (a later change by the caller does not reach the task, which runs only
// when a result is needed); shared_argument types (topologies) travel by reference.
#include <catch2/catch.hpp>

#include "flecsi_lite/data.hh"
#include "flecsi_lite/execution.hh"
#include "flecsi_lite/topology/narray.hh"

#include <cstdint>
#include <numeric>
#include <vector>

using namespace flecsi_lite;
using topology::narray;

namespace {
struct settings {
  double scale = 1.0;
};
const field<double>::definition<narray> values{"values"};

int twice(int x) { return 2 * x; }
double total(const std::vector<double>& v) { return std::accumulate(v.begin(), v.end(), 0.0); }
double scaled(const settings& s, double x) { return s.scale * x; }
std::uintptr_t address_of(const narray& n) { return reinterpret_cast<std::uintptr_t>(&n); }
void fill(const narray& n, field<double>::accessor<wo> f) {
  for (std::size_t i = 0; i < f.size(); ++i) f(i) = double(n.global_index(i));
}
double first(field<double>::accessor<ro> f) { return f.size() ? f(0) : -1.0; }

static_assert(execution::shared_argument_v<narray> && execution::shared_argument_v<const narray&>);
static_assert(!execution::shared_argument_v<std::vector<double>> && !execution::shared_argument_v<settings>);
}  // namespace

TEST_CASE("a value changed after the launch: the task sees the launch-time value") {
  int x = 1;
  auto doubled = execute<twice>(x);
  x = 5;
  CHECK(execution::executor::instance().pending() > 0);  // the task has not run yet
  CHECK(doubled.get() == 2);
}

TEST_CASE("a const reference is copied at launch") {
  std::vector<double> v{1.0, 2.0};
  settings s;
  auto sum = execute<total>(v);
  auto product = execute<scaled>(s, 3.0);
  v.assign(3, 10.0);  // the task, run later, would see 30 through a reference
  s.scale = -1.0;
  CHECK(execution::executor::instance().pending() > 0);
  CHECK(sum.get() == 3.0);
  CHECK(product.get() == 3.0);
}

TEST_CASE("a topology travels by reference") {
  narray n(16, 1, false);
  CHECK(execute<address_of>(n).get() == reinterpret_cast<std::uintptr_t>(&n));
  execute<fill>(n, values(n));
  CHECK(execute<first>(values(n)).get() == double(n.first_global()));
}
