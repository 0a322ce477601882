// The life of an output file written under `<path>.partial` (h5part_writer, snapshot_writer): a
// complete file is flushed, closed and renamed; an unfinished one is closed without ever leaving
// a rank waiting in parallel HDF5, whatever failed before.
#pragma once

#include "flecsi_lite/io/collective_agreement.hh"
#include "flecsi_lite/io/detail/hdf5_handle.hh"

#include <mpi.h>

#include <optional>
#include <string>

namespace flecsi_lite::io {

/// Collective: raise_if_any, and when any rank failed, sets `storage_failed` on every rank (a
/// failed data write or flush: afterwards the file is only emptied and closed, see below).
void raise_marking_storage_failure(MPI_Comm comm, const std::optional<failure_record>& failed, bool& storage_failed);

/// Collective: flushes and closes the complete `file` (`partial` is its path); a failed flush
/// marks `storage_failed` and leaves the file open for close_unfinished_file.
void finish_partial_file(MPI_Comm comm, hdf5_handle& file, const std::string& partial, bool& storage_failed);

/// Collective: renames `partial` to `path` on rank 0, refused when `path` has become something
/// else than a regular file; every rank returns once the rename is done.
void rename_partial_file(MPI_Comm comm, const std::string& partial, const std::string& path);

/// Collective, for a file that will not be finished: flushes and closes it and returns true, or,
/// after a storage failure or when the flush fails on any rank, empties `partial` first, closes
/// it and returns false (the file then has no content worth keeping).
///
/// A failed H5Fclose leaves HDF5 a half-closed file that crashes its clean-up in MPI_Finalize,
/// so the close must not fail. After a failed write or flush (a full disk) it must not even be
/// tried as it is: parallel HDF5 (1.10) then fails its metadata flush on the writing rank only,
/// skips the sync point's broadcast there and leaves the other ranks waiting in it for ever.
/// Emptying the file gives back the space the close needs. (libhdf5 1.10 may still print
/// "infinite loop closing library" at exit: blocks its failed flush leaked; the exit is clean.)
bool close_unfinished_file(MPI_Comm comm, hdf5_handle& file, const std::string& partial, bool storage_failed);

}  // namespace flecsi_lite::io
