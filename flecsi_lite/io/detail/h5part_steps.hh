// The steps of an open H5Part file: the indices k of its root groups named Step#k, in numeric
// order (Step#10 after Step#9, which a name sort would put after Step#1).
#pragma once

#include <hdf5.h>

#include <cstdint>
#include <string>
#include <vector>

namespace flecsi_lite::io::h5part {

/// Sorted step indices of the root groups named `groups`; other names are ignored.
std::vector<std::int64_t> step_indices(const std::vector<std::string>& groups);
/// The same for a file this process wrote (readers take the names from the forked listing,
/// metadata_listing.hh). Throws io_error when HDF5 fails.
std::vector<std::int64_t> step_indices(hid_t file);

}  // namespace flecsi_lite::io::h5part
