// Contiguous placement of per-rank arrays in a global array (see particle_partition.hh).
#include "flecsi_lite/io/particle_partition.hh"

namespace flecsi_lite::io {

placement place_contiguously(MPI_Comm comm, std::uint64_t local_count) {
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  placement result;
  std::uint64_t offset = 0;
  MPI_Exscan(&local_count, &offset, 1, MPI_UINT64_T, MPI_SUM, comm);
  if (rank == 0) offset = 0;  // MPI leaves rank 0's result undefined
  MPI_Allreduce(&local_count, &result.global_length, 1, MPI_UINT64_T, MPI_SUM, comm);
  result.local = {offset, local_count};
  return result;
}

}  // namespace flecsi_lite::io
