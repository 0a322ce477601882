// Opening an existing HDF5 file for reading on every rank of a communicator, with the checks
// that turn a wrong path or a damaged file into one clear error on every rank (the H5Part and
// the GADGET/SWIFT readers share it).
#pragma once

#include "flecsi_lite/io/detail/hdf5_handle.hh"
#include "flecsi_lite/io/detail/metadata_listing.hh"

#include <mpi.h>

#include <string>

namespace flecsi_lite::io {

struct opened_file {
  hdf5_handle file;
  /// The file's groups and datasets, listed by rank 0's check (the job iterates no link table).
  metadata_listing listing;
};

/// Collective. Rank 0 first checks that `path` is a readable regular file with an HDF5 signature
/// whose metadata a forked child can list and read without any HDF5 failure or crash
/// (h5part_precheck.hh); then every rank opens it read-only through MPI-IO. Throws file_error on
/// every rank when any check or any rank's open fails. `kind` names what the file should be in
/// the messages ("an H5Part file").
opened_file open_for_reading_collectively(const std::string& path, MPI_Comm comm, const std::string& kind);

}  // namespace flecsi_lite::io
