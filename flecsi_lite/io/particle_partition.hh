// Where each rank's particles lie in a global 1-D array: contiguous slices placed by an exclusive
// scan of the local counts (for writing), or a balanced block partition (for reading).
#pragma once

#include <mpi.h>

#include <cstdint>

namespace flecsi_lite::io {

/// The elements [offset, offset + count) of a global array.
struct slice {
  std::uint64_t offset = 0;
  std::uint64_t count = 0;
  friend bool operator==(const slice& a, const slice& b) { return a.offset == b.offset && a.count == b.count; }
};

/// Rank r of p gets floor(n / p) elements, plus one for the first n mod p ranks, in rank order.
constexpr slice block_slice(std::uint64_t global_length, int rank, int size) {
  const std::uint64_t r = static_cast<std::uint64_t>(rank), p = static_cast<std::uint64_t>(size);
  const std::uint64_t base = global_length / p, extra = global_length % p;
  return {r * base + (r < extra ? r : extra), base + (r < extra ? 1 : 0)};
}

/// This rank's slice when every rank's `local_count` elements follow those of the lower ranks,
/// and the global length. Collective.
struct placement {
  slice local;
  std::uint64_t global_length = 0;
};
placement place_contiguously(MPI_Comm comm, std::uint64_t local_count);

}  // namespace flecsi_lite::io
