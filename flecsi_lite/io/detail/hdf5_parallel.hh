// Property lists for parallel HDF5 over MPI-IO: file access through the MPI-IO driver on a
// communicator, and collective data transfers (every rank takes part in each read and write).
#pragma once

#include "flecsi_lite/io/detail/hdf5_handle.hh"

#include <mpi.h>

namespace flecsi_lite::io {

/// File access: MPI-IO driver on `comm`, collective metadata writes, and the HDF5 1.8 file
/// format as the oldest allowed (needed for attributes above 64 KiB, such as a long parameter
/// set; readable by every HDF5 since 1.8, hence by ParaView).
hdf5_handle mpio_file_access(MPI_Comm comm);

/// Data transfer: collective MPI-IO (H5FD_MPIO_COLLECTIVE).
hdf5_handle collective_transfer();

}  // namespace flecsi_lite::io
