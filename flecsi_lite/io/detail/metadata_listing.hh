// The names a reader needs from an HDF5 file's link tables (the groups of the root, the datasets
// of each of them), read once in a forked child (h5part_precheck.hh) and handed to every rank, so
// that the parallel job never iterates a link table: libhdf5 1.10 frees garbage in
// H5G__link_release_table after a failed iteration of a corrupted dense link heap, and leaks
// free-list blocks on that path ("infinite loop closing library" at exit).
#pragma once

#include <mpi.h>

#include <map>
#include <string>
#include <vector>

namespace flecsi_lite::io {

struct metadata_listing {
  /// The groups directly in the root, in name order.
  std::vector<std::string> groups;
  /// The datasets directly in each of those groups (and in the root, under ""), in name order.
  std::map<std::string, std::vector<std::string>> datasets;

  /// The datasets of `group`; empty when it has none or is not listed.
  const std::vector<std::string>& datasets_of(const std::string& group) const;
};

/// Bytes that carry a listing through a pipe or a broadcast, and back (throws std::runtime_error
/// on bytes that are not an encoded listing).
std::string encode(const metadata_listing& listing);
metadata_listing decode_listing(const std::string& bytes);

/// Collective: every rank gets `root`'s listing.
metadata_listing broadcast_listing(const metadata_listing& listing, int root, MPI_Comm comm);

}  // namespace flecsi_lite::io
