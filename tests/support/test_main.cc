// Catch2 main for unit and MPI tests: MPI and Kokkos live for the whole test session. Every rank
// runs every test case; a failure on any rank makes mpiexec fail.
#define CATCH_CONFIG_RUNNER
#include <catch2/catch.hpp>

#include "flecsi_lite/runtime/context.hh"

#include <mpi.h>
#include <Kokkos_Core.hpp>

int main(int argc, char** argv) {
  int provided = 0;
  MPI_Init_thread(&argc, &argv, MPI_THREAD_FUNNELED, &provided);
  Kokkos::initialize(argc, argv);
  int result = 0;
  {
    Catch::Session session;
    result = session.applyCommandLine(argc, argv);
    if (result == 0) result = session.run();
  }
  // Agree on the outcome so that every rank exits with the same code.
  int worst = 0;
  MPI_Allreduce(&result, &worst, 1, MPI_INT, MPI_MAX, flecsi_lite::runtime::communicator());
  Kokkos::finalize();
  MPI_Finalize();
  return worst;
}
