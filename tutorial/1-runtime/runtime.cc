// Tutorial chapter 1: a flecsi_lite program's runtime. runtime::runtime starts MPI and Kokkos,
// parses the command line against declared options, and at the end prints the timer summary.
//
//   mpirun -np 2 tutorial_1_runtime --name reader --repeat 3
#include "flecsi_lite/runtime.hh"

#include <mpi.h>

#include <cmath>
#include <string>

using namespace flecsi_lite;

int main(int argc, char** argv) {
  // Options are declared before the runtime starts; --help, --no-timers, --log-all-ranks,
  // --trace and --control-model come with every program.
  runtime::options options("Tutorial 1: start-up, options, logging and timers.");
  options.value("name", "WHO", "whom to greet", "world")
    .value("repeat", "N", "how many times to time the work", "2")
    .flag("loud", "greet from every rank");
  runtime::runtime rt(argc, argv, options);
  if (!rt.proceed()) return rt.exit_code();  // --help printed, or a bad option (status 2)

  const std::string name = rt.opts().get("name");
  const int repeat = std::stoi(rt.opts().get("repeat"));
  if (rt.opts().has("loud")) log::set_all_ranks(true);

  // Logging: rank 0 speaks (every rank with --log-all-ranks); the line prints as the message
  // goes out of scope. Errors and warnings always print.
  log::info() << "hello, " << name << ", from rank " << runtime::rank() << " of " << runtime::size();

  // Timers: a scoped timer adds its lifetime to a named timer; the summary at exit shows the
  // minimum, mean and maximum over ranks.
  double work = 0;
  for (int r = 0; r < repeat; ++r) {
    timers::scoped timer("tutorial work");
    for (int i = 1; i <= 100000; ++i) work += 1.0 / (double(i) * i);
  }

  // Checks: every rank agrees on the rank count, the timer counted each repetition, and the work
  // approached pi^2 / 6. The framework's communicator is runtime::communicator().
  int ranks_seen = 0, one = 1;
  MPI_Allreduce(&one, &ranks_seen, 1, MPI_INT, MPI_SUM, runtime::communicator());
  bool correct = ranks_seen == runtime::size() && repeat > 0;
  correct &= std::abs(work / repeat - 3.14159265358979323846 * 3.14159265358979323846 / 6) < 1e-4;
  long calls = 0;
  for (const auto& row : timers::summarize())  // collective: every rank calls it
    if (row.name == "tutorial work") calls = row.calls;
  if (runtime::rank() == 0) correct &= calls == repeat;
  int all_correct = correct;
  MPI_Allreduce(MPI_IN_PLACE, &all_correct, 1, MPI_INT, MPI_LAND, runtime::communicator());
  if (!all_correct) log::error() << "tutorial 1: wrong rank count, timer calls or work";
  return all_correct ? 0 : 1;
}
