// The memory of a job's ranks (job_memory.hh).
#include "flecsi_lite/runtime/job_memory.hh"

#if defined(__GLIBC__)
#include <malloc.h>
#endif
#include <sys/resource.h>
#include <unistd.h>

#include <algorithm>
#include <fstream>
#include <limits>
#include <string>

namespace flecsi_lite::runtime {

namespace {
constexpr double unlimited = std::numeric_limits<double>::infinity();

/// The number in `path` (a control group's limit), or +inf when it is absent or not a number
/// ("max" in cgroup v2; v1 writes a huge number for none, which is larger than any machine).
double limit_in(const char* path) {
  std::ifstream in(path);
  std::string text;
  if (!(in >> text) || text.empty() || text.find_first_not_of("0123456789") != std::string::npos) return unlimited;
  return std::stod(text);
}
}  // namespace

double rank_memory_limit() {
  double limit = unlimited;
  rlimit address_space{};
  if (getrlimit(RLIMIT_AS, &address_space) == 0 && address_space.rlim_cur != RLIM_INFINITY)
    limit = double(address_space.rlim_cur);
  limit = std::min(limit, limit_in("/sys/fs/cgroup/memory.max"));
  return std::min(limit, limit_in("/sys/fs/cgroup/memory/memory.limit_in_bytes"));
}

double physical_memory() {
  const long pages = sysconf(_SC_PHYS_PAGES), page_size = sysconf(_SC_PAGESIZE);
  return pages > 0 && page_size > 0 ? double(pages) * double(page_size) : unlimited;
}

double detect_job_memory(MPI_Comm comm) {
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm node;
  MPI_Comm_split_type(comm, MPI_COMM_TYPE_SHARED, rank, MPI_INFO_NULL, &node);
  int node_rank = 0;
  MPI_Comm_rank(node, &node_rank);
  // An upper bound, so that a refusal is never wrong: a control group that the node's ranks share
  // counts once per rank here.
  double own = rank_memory_limit(), node_limits = 0;
  MPI_Allreduce(&own, &node_limits, 1, MPI_DOUBLE, MPI_SUM, node);
  MPI_Comm_free(&node);
  const double node_memory = node_rank == 0 ? std::min(physical_memory(), node_limits) : 0.0;
  double job = 0;
  MPI_Allreduce(&node_memory, &job, 1, MPI_DOUBLE, MPI_SUM, comm);
  return job;
}

void return_free_memory() {
#if defined(__GLIBC__)
  malloc_trim(0);
#endif
}

}  // namespace flecsi_lite::runtime
