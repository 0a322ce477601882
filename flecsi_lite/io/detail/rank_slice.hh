// A rank's part of a dataset of particles for a collective read or write: the rows
// [offset, offset + rows) selected in the file's dataspace, and the dataspace of that part in
// memory. One selection for the H5Part reader and writer, the snapshot writer and the GADGET
// reader: every rank takes part in the collective transfer, a rank without rows with empty
// selections in both spaces.
#pragma once

#include "flecsi_lite/io/detail/hdf5_handle.hh"

#include <hdf5.h>

#include <string>

namespace flecsi_lite::io {

/// The file and memory dataspaces of a rank's part of a dataset.
struct rank_slice {
  hdf5_handle file_space, memory_space;
};

/// Selects in `dataset` the rows [offset, offset + rows), columns [first_column, first_column +
/// columns) of a 2-D dataset (a 1-D one has rows only, and the columns are ignored), and makes the
/// memory dataspace of `memory_rank` dimensions: {rows} or {rows, columns}. Throws io_error
/// ("cannot select this rank's part of <what>") when HDF5 cannot.
rank_slice select_rank_slice(hid_t dataset, hsize_t offset, hsize_t rows, hsize_t first_column, hsize_t columns,
                             int memory_rank, const std::string& what);

}  // namespace flecsi_lite::io
