// Tutorial chapter 3: the execution model. A task is a plain function; execute<task>(args...)
// launches it and returns a future, reduce<task, op>(args...) combines its result over the ranks.
// The privileges in a task's accessor parameters (ro, wo, rw, na for owned and ghost entities)
// tell the executor which launches depend on which: the program reads as sequential code.
//
//   mpirun -np 2 tutorial_3_execution
#include "flecsi_lite/execution.hh"
#include "flecsi_lite/data.hh"
#include "flecsi_lite/runtime.hh"
#include "flecsi_lite/topology/narray.hh"

#include <cstdint>

using namespace flecsi_lite;
using topology::narray;

namespace {
const field<double>::definition<narray> values{"values"};

// wo: every owned value is written and none is read, so earlier values need not be valid.
void fill(const narray& mesh, field<double>::accessor<wo> v) {
  forall(v.size(), [&](std::size_t i) { v(i) = double(mesh.global_index(i)); });
}
// rw: reads and writes owned values. `factor` is a double: a future<double> may be passed, and
// the task then waits for the launch producing it.
void scale(field<double>::accessor<rw> v, double factor) {
  forall(v.size(), [&](std::size_t i) { v(i) *= factor; });
}
// ro: reads only. A task's return value reaches the caller through its future.
double local_sum(field<double>::accessor<ro> v) {
  double sum = 0;
  for (std::size_t i = 0; i < v.size(); ++i) sum += v(i);
  return sum;
}
double local_max(field<double>::accessor<ro> v) {
  double largest = v.size() ? v(0) : 0;
  for (std::size_t i = 0; i < v.size(); ++i) largest = std::max(largest, v(i));
  return largest;
}
std::uint64_t local_count(field<double>::accessor<ro> v) { return v.size(); }
double inverse(double x) { return 1 / x; }
}  // namespace

int main(int argc, char** argv) {
  runtime::runtime rt(argc, argv, runtime::options("Tutorial 3: tasks, futures and privileges."));
  if (!rt.proceed()) return rt.exit_code();
  const std::size_t n = 1000;
  narray mesh(n, 0, false);  // the index space the field lives on: n entities split over ranks

  execute<fill>(mesh, values(mesh));
  // Each rank's sum, then the sum over ranks in rank order (bitwise the same on every rank);
  // exact_sum is moreover independent of the rank count.
  future<double> total = reduce<local_sum, reduction::exact_sum>(values(mesh));
  future<double> largest = reduce<local_max, reduction::max>(values(mesh));
  future<std::uint64_t> count = reduce<local_count, reduction::sum>(values(mesh));
  // A future as an argument: inverse waits for `largest`; scale waits for inverse and, because
  // it writes `values`, for the three reductions reading them (write after read).
  future<double> factor = execute<inverse>(largest);
  execute<scale>(values(mesh), factor);
  future<double> normalized = reduce<local_max, reduction::max>(values(mesh));

  // get() runs the executor until the value is there.
  const double expected_total = double(n) * double(n - 1) / 2;
  const bool correct =
    total.get() == expected_total && largest.get() == double(n - 1) && count.get() == n && normalized.get() == 1.0;
  log::info() << "sum " << total.get() << ", max " << largest.get() << ", entities " << count.get()
              << ", max after scaling " << normalized.get();
  if (!correct) log::error() << "tutorial 3: wrong reduction results";
  return correct ? 0 : 1;
}
