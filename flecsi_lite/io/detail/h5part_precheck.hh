// Protection of the collective open from corrupted metadata: libhdf5 1.10 frees garbage pointers
// on some error paths (H5G__link_release_table after a corrupted fractal heap of dense link
// storage) and crashes the whole job. The walk is made first in a child process.
#pragma once

#include <string>

namespace flecsi_lite::io::h5part {

/// Serial, not collective (rank 0 calls it before the collective open): a forked child opens
/// `path` with HDF5's serial driver and touches every piece of metadata the reader can touch
/// (the links of the root and of each group, every object header, dataspace, datatype, creation
/// properties and storage size of each dataset, every attribute and its value). Returns "" when
/// the child ends normally, whatever HDF5 reported (the reader then gives its own message), or
/// why the file cannot be read safely: the signal the child died of, or that it did not end
/// within `seconds`.
std::string metadata_crash_check(const std::string& path, double seconds = 120);

}  // namespace flecsi_lite::io::h5part
