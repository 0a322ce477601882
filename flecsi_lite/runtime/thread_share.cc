// Threads per rank (thread_share.hh): the node's ranks and cores from MPI and the affinity masks,
// the user's choice from the environment and the command line, and the argv handed to Kokkos.
#include "flecsi_lite/runtime/thread_share.hh"

#include "flecsi_lite/runtime/log.hh"

#include <sched.h>
#include <Kokkos_Core.hpp>

#include <algorithm>
#include <cstdlib>
#include <cstring>
#include <thread>
#include <vector>

namespace flecsi_lite::runtime {
namespace {
// The arguments handed to Kokkos live as long as the program (argv points into them).
std::vector<std::string> kokkos_argument_text;
std::vector<char*> kokkos_argument_pointers;

bool starts_with(const std::string& text, const std::string& prefix) { return text.rfind(prefix, 0) == 0; }

/// A positive integer, or 0 when `text` is not one.
int positive_integer(const std::string& text) {
  if (text.empty() || text.size() > 6 ||
      !std::all_of(text.begin(), text.end(), [](char c) { return c >= '0' && c <= '9'; }))
    return 0;
  return std::atoi(text.c_str());
}

/// The thread count of an environment variable ("4", or "4,2" for nested levels), 0 when unset.
int environment_threads(const char* name) {
  const char* value = std::getenv(name);
  if (!value || !*value) return 0;
  const std::string text(value);
  const int threads = positive_integer(text.substr(0, text.find(',')));
  return threads > 0 ? threads : 1;  // set but unreadable: still the user's choice; OpenMP decides
}

/// "--kokkos-threads" or "--kokkos-num-threads" when `argument` is one of them (with or without
/// "=N"), else "".
std::string thread_option_name(const std::string& argument) {
  for (const char* name : {"--kokkos-num-threads", "--kokkos-threads"}) {
    const std::string n(name);
    if (argument == n || starts_with(argument, n + "=")) return n;
  }
  return "";
}

/// The cores of the node of `node_comm`: the union of its ranks' affinity masks.
int node_cores(MPI_Comm node_comm) {
  cpu_set_t mask;
  CPU_ZERO(&mask);
  int known = sched_getaffinity(0, sizeof(mask), &mask) == 0 ? 1 : 0, all_known = 0;
  MPI_Allreduce(&known, &all_known, 1, MPI_INT, MPI_MIN, node_comm);
  if (!all_known) return static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  cpu_set_t node_mask;
  MPI_Allreduce(&mask, &node_mask, sizeof(cpu_set_t), MPI_BYTE, MPI_BOR, node_comm);
  return std::max(1, CPU_COUNT(&node_mask));
}
}  // namespace

const char* kokkos_thread_option() {
#if KOKKOS_VERSION >= 40000
  return "--kokkos-num-threads";
#else
  return "--kokkos-threads";
#endif
}

node_resources detect_node_resources(MPI_Comm comm) {
  MPI_Comm node_comm;
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_split_type(comm, MPI_COMM_TYPE_SHARED, rank, MPI_INFO_NULL, &node_comm);
  node_resources node;
  MPI_Comm_size(node_comm, &node.ranks);
  node.cores = node_cores(node_comm);
  MPI_Comm_free(&node_comm);
  return node;
}

thread_choice user_thread_choice(int argc, const char* const* argv) {
  thread_choice choice;
  for (int i = 1; i < argc; ++i) {  // the command line wins over the environment; the last one counts
    const std::string argument = argv[i];
    const std::string name = thread_option_name(argument);
    if (name.empty()) continue;
    const bool separate = argument == name;
    const std::string value = separate ? (i + 1 < argc ? argv[++i] : "") : argument.substr(name.size() + 1);
    choice.source = name;
    choice.threads = positive_integer(value);
    choice.error =
      choice.threads > 0 ? "" : "option '" + name + "' needs a positive number of threads, not '" + value + "'";
  }
  if (!choice.source.empty()) return choice;
  for (const char* variable : {"OMP_NUM_THREADS", "KOKKOS_NUM_THREADS"})
    if (const int threads = environment_threads(variable); threads > 0) return {threads, variable, ""};
  return choice;
}

std::string detail::prepare_kokkos_threads(int& argc, char**& argv) {
  const thread_choice choice = user_thread_choice(argc, argv);
  const std::string option = kokkos_thread_option();
  kokkos_argument_text.clear();
  for (int i = 0; i < argc; ++i) {
    const std::string argument = argv[i];
    if (i == 0 || thread_option_name(argument).empty()) {
      kokkos_argument_text.push_back(argument);
      continue;
    }
    // Both spellings become the one this Kokkos accepts; "--option N" becomes "--option=N".
    const std::string value = argument == thread_option_name(argument) ? (i + 1 < argc ? argv[++i] : "")
                                                                       : argument.substr(argument.find('=') + 1);
    if (positive_integer(value) > 0) kokkos_argument_text.push_back(option + "=" + value);
  }
  // Collective on every rank alike, whatever the user chose (the node's layout is needed anyway).
  const node_resources node = detect_node_resources(MPI_COMM_WORLD);
  if (choice.threads == 0)
    kokkos_argument_text.push_back(option + "=" + std::to_string(threads_per_rank(node.cores, node.ranks)));
  kokkos_argument_pointers.clear();
  for (auto& text : kokkos_argument_text) kokkos_argument_pointers.push_back(text.data());
  kokkos_argument_pointers.push_back(nullptr);
  argc = static_cast<int>(kokkos_argument_text.size());
  argv = kokkos_argument_pointers.data();
  return choice.error;
}

void detail::warn_if_oversubscribed(MPI_Comm comm) {
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm node_comm;
  MPI_Comm_split_type(comm, MPI_COMM_TYPE_SHARED, rank, MPI_INFO_NULL, &node_comm);
  const int threads = Kokkos::DefaultHostExecutionSpace().concurrency();
  int node_threads = 0, node_ranks = 0, max_threads = 0;
  MPI_Allreduce(&threads, &node_threads, 1, MPI_INT, MPI_SUM, node_comm);
  MPI_Allreduce(&threads, &max_threads, 1, MPI_INT, MPI_MAX, node_comm);
  MPI_Comm_size(node_comm, &node_ranks);
  const int cores = node_cores(node_comm);
  MPI_Comm_free(&node_comm);
  int excess = std::max(0, node_threads - cores), worst = 0;
  MPI_Allreduce(&excess, &worst, 1, MPI_INT, MPI_MAX, comm);
  if (rank != 0 || worst == 0) return;
  auto warning = log::warn();
  if (excess > 0)
    warning << node_ranks << " MPI ranks x " << max_threads << " threads exceed the " << cores
            << " cores of their node (they time-share the cores)";
  else
    warning << "on some node the MPI ranks x threads exceed the cores (they time-share the cores)";
  if (max_threads > 1)
    warning << "; use fewer threads (OMP_NUM_THREADS or " << kokkos_thread_option() << "=N)";
  else
    warning << "; use fewer ranks";
}

}  // namespace flecsi_lite::runtime
