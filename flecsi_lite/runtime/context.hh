// The MPI context of a run: rank, size and the communicator the framework uses.
#pragma once

#include <mpi.h>

#include <stdexcept>
#include <string>

namespace flecsi_lite::runtime {

/// The communicator all framework collectives use (a duplicate of MPI_COMM_WORLD, so that
/// application messages never match the framework's).
MPI_Comm communicator();
int rank();
int size();

/// Throws std::runtime_error naming `what` when an MPI call fails.
inline void check_mpi(int code, const char* what) {
  if (code == MPI_SUCCESS) return;
  char message[MPI_MAX_ERROR_STRING];
  int length = 0;
  MPI_Error_string(code, message, &length);
  throw std::runtime_error(std::string(what) + ": " + std::string(message, length));
}

namespace detail {
void set_communicator(MPI_Comm comm);
}

}  // namespace flecsi_lite::runtime
