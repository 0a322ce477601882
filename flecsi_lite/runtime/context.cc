#include "flecsi_lite/runtime/context.hh"

namespace flecsi_lite::runtime {
namespace {
MPI_Comm framework_comm = MPI_COMM_NULL;
}

MPI_Comm communicator() { return framework_comm == MPI_COMM_NULL ? MPI_COMM_WORLD : framework_comm; }

int rank() {
  int r = 0;
  MPI_Comm_rank(communicator(), &r);
  return r;
}

int size() {
  int s = 1;
  MPI_Comm_size(communicator(), &s);
  return s;
}

void detail::set_communicator(MPI_Comm comm) { framework_comm = comm; }

}  // namespace flecsi_lite::runtime
