// Plausibility bounds on declared HDF5 extents (see hdf5_storage.hh).
#include "flecsi_lite/io/detail/hdf5_storage.hh"

#include "flecsi_lite/io/detail/hdf5_handle.hh"

#include <limits>

namespace flecsi_lite::io {

std::uint64_t storable_elements(hid_t dataset, std::uint64_t element_size, std::uint64_t file_size) {
  if (element_size == 0) return 0;
  std::uint64_t bytes = file_size;
  auto creation = property_list_handle(H5Dget_create_plist(dataset));
  // Without the creation list we cannot see filters: allow the larger, compressed bound.
  const bool filtered = !creation || H5Pget_nfilters(creation.get()) != 0;
  if (filtered)
    bytes = file_size > std::numeric_limits<std::uint64_t>::max() / largest_compression_ratio
              ? std::numeric_limits<std::uint64_t>::max()
              : file_size * largest_compression_ratio;
  return bytes / element_size;
}

std::uint64_t file_size_of(hid_t location) {
  auto file = file_handle(H5Iget_file_id(location));
  hsize_t size = 0;
  if (!file || H5Fget_filesize(file.get(), &size) < 0) return 0;
  return size;
}

}  // namespace flecsi_lite::io
