// The rank's part of a dataset (rank_slice.hh).
#include "flecsi_lite/io/detail/rank_slice.hh"

#include "flecsi_lite/io/detail/hdf5_errors.hh"
#include "flecsi_lite/io/io_error.hh"

#include <algorithm>

namespace flecsi_lite::io {

rank_slice select_rank_slice(hid_t dataset, hsize_t offset, hsize_t rows, hsize_t first_column, hsize_t columns,
                             int memory_rank, const std::string& what) {
  rank_slice slice;
  slice.file_space = dataspace_handle(H5Dget_space(dataset));
  const int file_rank = slice.file_space ? H5Sget_simple_extent_ndims(slice.file_space.get()) : -1;
  const hsize_t start[2] = {offset, first_column}, count[2] = {rows, columns};
  slice.memory_space = dataspace_handle(H5Screate_simple(memory_rank, count, nullptr));
  const herr_t selected =
    !slice.file_space || !slice.memory_space ? -1
    : rows > 0 ? H5Sselect_hyperslab(slice.file_space.get(), H5S_SELECT_SET, start, nullptr, count, nullptr)
               : std::min(H5Sselect_none(slice.file_space.get()), H5Sselect_none(slice.memory_space.get()));
  if (file_rank < 1 || selected < 0)
    throw io_error(failure::system, "cannot select this rank's part of " + what + hdf5_reason());
  return slice;
}

}  // namespace flecsi_lite::io
