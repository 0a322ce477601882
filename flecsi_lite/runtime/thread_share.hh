// Threads per rank: unless the user chose (OMP_NUM_THREADS, KOKKOS_NUM_THREADS, or Kokkos' thread
// option on the command line), each rank gets its share of the cores of its node.
//
// Vocabulary: the NODE of a rank is the set of ranks sharing its memory (MPI_COMM_TYPE_SHARED);
// its CORES are the processors those ranks may run on, the union of their affinity masks (mpirun
// may bind each rank to one core, so one rank's own mask would undercount the node).
#pragma once

#include <mpi.h>

#include <string>

namespace flecsi_lite::runtime {

/// The threads of one rank: `chosen` when the user chose (chosen > 0), otherwise the rank's share
/// of its node's cores, cores / ranks_on_node rounded down, at least 1.
constexpr int threads_per_rank(int cores, int ranks_on_node, int chosen = 0) {
  if (chosen > 0) return chosen;
  const int share = ranks_on_node > 0 ? cores / ranks_on_node : cores;
  return share > 0 ? share : 1;
}

/// The ranks on this rank's node and the cores they may run on. Collective over `comm`.
struct node_resources {
  int ranks = 1;
  int cores = 1;
};
node_resources detect_node_resources(MPI_Comm comm);

/// What the user chose: a thread count (0 when none), where it came from ("OMP_NUM_THREADS",
/// "--kokkos-num-threads", ...) and, for a command-line value that is no positive integer, an error.
struct thread_choice {
  int threads = 0;
  std::string source;
  std::string error;
};
/// Reads the environment and argv[1..argc) (both Kokkos spellings of the option, `=N` or ` N`).
thread_choice user_thread_choice(int argc, const char* const* argv);

/// The spelling of the thread option the Kokkos this program is built with accepts:
/// "--kokkos-threads" before Kokkos 4, "--kokkos-num-threads" from Kokkos 4 on.
const char* kokkos_thread_option();

namespace detail {
/// Before Kokkos::initialize: rewrites argc/argv so that Kokkos gets the thread option in its own
/// spelling and, unless the user chose, this rank's share. Returns the error of a bad thread
/// option ("" when none; the option is then dropped). Collective over MPI_COMM_WORLD.
std::string prepare_kokkos_threads(int& argc, char**& argv);
/// After Kokkos::initialize: rank 0 warns, once, when the ranks x threads of a node exceed its
/// cores. Collective over `comm`.
void warn_if_oversubscribed(MPI_Comm comm);
}  // namespace detail

}  // namespace flecsi_lite::runtime
