// One rank's task throws while the others go on and wait for its ghost values and its part of a
// reduction: the run must end (not hang) with the failure's message and a non-zero status.
// Run by expect_abort.sh, which checks the status and the message.
#include "flecsi_lite/data.hh"
#include "flecsi_lite/execution.hh"
#include "flecsi_lite/runtime.hh"
#include "flecsi_lite/topology/narray.hh"

#include <iostream>
#include <stdexcept>

using namespace flecsi_lite;
using topology::narray;

namespace {
const field<double>::definition<narray> a{"a"};

void set(field<double>::accessor<wo> f, double v) {
  for (std::size_t i = 0; i < f.size(); ++i) f(i) = v;
}
void fail_on_last_rank(field<double>::accessor<rw> f) {
  if (runtime::rank() + 1 == runtime::size()) throw std::runtime_error("deliberate failure on the last rank");
  f(0) += 1;
}
double sum_with_ghosts(field<double>::accessor<ro, ro> f) {
  double s = 0;
  for (std::size_t i = 0; i < f.size(); ++i) s += f(i);
  return s;
}
}  // namespace

int main(int argc, char** argv) {
  runtime::runtime rt(argc, argv);
  if (!rt.proceed()) return rt.exit_code();
  try {
    narray n(64, 2, true);
    execute<set>(a(n), 1.0);
    execute<fail_on_last_rank>(a(n));
    for (int step = 0; step < 3; ++step)  // needs every rank's ghosts and values
      std::cout << "rank " << runtime::rank() << ": " << reduce<sum_with_ghosts, reduction::sum>(a(n)).get()
                << std::endl;
  } catch (const std::exception& e) {
    std::cerr << "rank " << runtime::rank() << " caught: " << e.what() << std::endl;
    return 3;
  }
  return 0;
}
