// The memory the ranks of a job may use together, found once at start-up, so that a particle
// count that cannot fit is a parameter error naming its keys (derived_values.hh:
// checked_particles; issue 38, item 9) rather than a failed allocation, or the kernel's
// out-of-memory killer, in the middle of the set-up.
#pragma once

#include <mpi.h>

#include <cstdint>

namespace flecsi_lite::runtime {

/// The bytes one rank may use by itself: the smaller of its soft address-space limit (ulimit -v)
/// and its control group's memory limit (cgroup v2 memory.max, v1 memory.limit_in_bytes); +inf
/// when neither is set.
double rank_memory_limit();

/// The bytes of this machine's physical memory (sysconf).
double physical_memory();

/// Collective over `comm`: per node (the ranks sharing memory, MPI_COMM_TYPE_SHARED) the smaller
/// of its physical memory and the sum of its ranks' rank_memory_limit(), summed over the nodes:
/// an upper bound of what the job can allocate.
double detect_job_memory(MPI_Comm comm);

/// Gives the memory the allocator holds free back to the system (glibc: malloc_trim; elsewhere
/// nothing), so that a rank's resident size is what it uses. glibc keeps large freed blocks in
/// its heap once a block of their size was freed (its mmap threshold rises to it), and counts
/// them resident: Sedov 3D 100^3 peaked at 731 MB instead of 654 MB (docs/performance.md,
/// "Neighbour lists as runs"). Call it where large arrays were just freed.
void return_free_memory();

}  // namespace flecsi_lite::runtime
