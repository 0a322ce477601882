// The runtime's threads per rank, run under mpiexec: with no choice in the environment each rank
// runs Kokkos with its share of the node's cores; otherwise with what the user chose.
//   threads_per_rank share | threads_per_rank <n> [program options]   (exit 1 on a mismatch)
#include "flecsi_lite/runtime.hh"

#include <Kokkos_Core.hpp>

#include <cstdlib>
#include <iostream>
#include <string>

int main(int argc, char** argv) {
  const std::string expected = argc > 1 ? argv[1] : "share";
  flecsi_lite::runtime::options options;
  options.positional("expected", "share, or the thread count the user chose");
  flecsi_lite::runtime::runtime rt(argc, argv, options);
  if (!rt.proceed()) return rt.exit_code();
  const auto node = flecsi_lite::runtime::detect_node_resources(flecsi_lite::runtime::communicator());
  // Independent of the affinity masks: the ranks on this node are those with its processor name.
  char name[MPI_MAX_PROCESSOR_NAME] = {};
  int length = 0;
  MPI_Get_processor_name(name, &length);
  const int size = flecsi_lite::runtime::size();
  std::string all(static_cast<std::size_t>(size) * MPI_MAX_PROCESSOR_NAME, '\0');
  MPI_Allgather(name, MPI_MAX_PROCESSOR_NAME, MPI_CHAR, all.data(), MPI_MAX_PROCESSOR_NAME, MPI_CHAR,
                flecsi_lite::runtime::communicator());
  int same_node = 0;
  for (int r = 0; r < size; ++r) same_node += std::string(all.c_str() + r * MPI_MAX_PROCESSOR_NAME) == name;

  const int threads = Kokkos::DefaultHostExecutionSpace().concurrency();
  const int wanted =
    expected == "share" ? flecsi_lite::runtime::threads_per_rank(node.cores, node.ranks) : std::atoi(expected.c_str());
  int node_threads = 0;
  MPI_Allreduce(&threads, &node_threads, 1, MPI_INT, MPI_SUM, flecsi_lite::runtime::communicator());
  bool ok = threads == wanted && node.ranks == same_node && node.cores >= 1;
  // The share never oversubscribes a node that has a core for every rank.
  if (expected == "share" && node.ranks <= node.cores) ok = ok && node_threads <= node.cores * (size / node.ranks);
  if (!ok)
    std::cerr << "rank " << flecsi_lite::runtime::rank() << ": " << threads << " threads, expected " << wanted << " ("
              << expected << "; node: " << node.ranks << " ranks of " << same_node << ", " << node.cores << " cores)\n";
  int failed = !ok, any = 0;
  MPI_Allreduce(&failed, &any, 1, MPI_INT, MPI_MAX, flecsi_lite::runtime::communicator());
  return any;
}
