// The life of an output file written under `<path>.partial` (h5part_writer, snapshot_writer): a
// complete file is flushed, closed and renamed; an unfinished one is closed without ever leaving
// a rank waiting in parallel HDF5, whatever failed before. The class partial_file holds that
// life cycle (open -> finish -> commit, or abandoned unfinished) once for both writers.
#pragma once

#include "flecsi_lite/io/collective_agreement.hh"
#include "flecsi_lite/io/detail/hdf5_handle.hh"

#include <mpi.h>

#include <optional>
#include <string>
#include <utility>

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

/// A file written as `<path>.partial`, then FINISHED (flushed and closed, complete: it awaits
/// its commit) and COMMITTED (renamed to `<path>`, so that an earlier file of that name is
/// replaced only by a complete one, and only once the run that wrote it says so). A writer opens
/// file() itself and, should it be destroyed before the commit, abandons it by its own rule
/// (close_unfinished). Every member function that touches the file is collective over `comm`.
class partial_file {
 public:
  partial_file(std::string path, MPI_Comm comm) : path_(std::move(path)), comm_(comm) {}

  const std::string& path() const { return path_; }
  std::string partial_path() const { return path_ + ".partial"; }
  /// The open file (set by the writer that opens it).
  hdf5_handle& file() { return file_; }
  const hdf5_handle& file() const { return file_; }
  bool is_open() const { return file_.valid(); }
  /// Finished and not yet committed.
  bool awaits_commit() const { return committing_; }
  /// Whether a data write or flush failed on some rank (the file is then only emptied and closed).
  bool storage_failed() const { return storage_failed_; }

  /// Collective: raise_if_any, remembering a failure as a storage failure.
  void raise_marking_storage_failure(const std::optional<failure_record>& failed) {
    io::raise_marking_storage_failure(comm_, failed, storage_failed_);
  }
  /// Collective: flushes and closes the complete file, which then awaits commit(); a failed flush
  /// leaves it open for the writer's abandon. Nothing when the file is not open.
  void finish() {
    if (!is_open()) return;
    finish_partial_file(comm_, file_, partial_path(), storage_failed_);
    committing_ = true;
  }
  /// Collective, after finish(): the rename of `<path>.partial` to `<path>`; nothing otherwise.
  void commit() {
    if (!committing_) return;
    rename_partial_file(comm_, partial_path(), path_);
    committing_ = false;
  }
  /// Collective, for a file that will not be finished: close_unfinished_file.
  bool close_unfinished() { return close_unfinished_file(comm_, file_, partial_path(), storage_failed_); }

 private:
  std::string path_;
  MPI_Comm comm_;
  hdf5_handle file_;
  bool committing_ = false;
  bool storage_failed_ = false;
};

}  // namespace flecsi_lite::io
