// Protection of the collective open from corrupted metadata: libhdf5 1.10 frees garbage pointers
// on some error paths (H5G__link_release_table after a failed iteration of a corrupted dense link
// heap) and crashes the whole job, and leaks free-list blocks there ("infinite loop closing
// library" at exit). Every link table is iterated in a child process, never in the job.
#pragma once

#include "flecsi_lite/io/detail/metadata_listing.hh"

#include <string>

namespace flecsi_lite::io::h5part {

/// What the child found: the names the reader needs, or why the file cannot be read.
struct metadata_check {
  std::string problem;  ///< "" when the file's metadata can be read safely
  metadata_listing listing;
};

/// Serial, not collective (rank 0 calls it before the collective open): a forked child opens
/// `path` with HDF5's serial driver, lists the groups of the root and the datasets of each, and
/// touches every piece of metadata the reader can touch (every object header, dataspace,
/// datatype, creation properties and storage size of each dataset, every attribute and its
/// value). `problem` names the file and what failed when HDF5 cannot list a group, open an object
/// of a hard link, inspect a dataset or read an attribute, when the child crashed (the signal), or
/// when it did not end within `seconds`.
metadata_check check_metadata(const std::string& path, double seconds = 120);

}  // namespace flecsi_lite::io::h5part
