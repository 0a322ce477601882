// Property lists for parallel HDF5 (see hdf5_parallel.hh).
#include "flecsi_lite/io/detail/hdf5_parallel.hh"

#include "flecsi_lite/io/detail/hdf5_errors.hh"
#include "flecsi_lite/io/io_error.hh"

namespace flecsi_lite::io {

hdf5_handle mpio_file_access(MPI_Comm comm) {
  auto access = property_list_handle(H5Pcreate(H5P_FILE_ACCESS));
  if (!access || H5Pset_fapl_mpio(access.get(), comm, MPI_INFO_NULL) < 0 ||
      H5Pset_coll_metadata_write(access.get(), true) < 0 ||
      H5Pset_libver_bounds(access.get(), H5F_LIBVER_V18, H5F_LIBVER_LATEST) < 0)
    throw io_error(failure::system, "cannot set up MPI-IO file access" + hdf5_reason());
  return access;
}

hdf5_handle collective_transfer() {
  auto transfer = property_list_handle(H5Pcreate(H5P_DATASET_XFER));
  if (!transfer || H5Pset_dxpl_mpio(transfer.get(), H5FD_MPIO_COLLECTIVE) < 0)
    throw io_error(failure::system, "cannot set up collective transfers" + hdf5_reason());
  return transfer;
}

}  // namespace flecsi_lite::io
