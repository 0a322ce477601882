// Finishing, renaming and abandoning files written under a temporary name (partial_file.hh).
#include "flecsi_lite/io/detail/partial_file.hh"

#include "flecsi_lite/io/detail/hdf5_errors.hh"
#include "flecsi_lite/io/output_path.hh"

#include <hdf5.h>

#include <filesystem>
#include <system_error>

namespace flecsi_lite::io {

void raise_marking_storage_failure(MPI_Comm comm, const std::optional<failure_record>& failed, bool& storage_failed) {
  try {
    raise_if_any(comm, failed);
  } catch (...) {
    storage_failed = true;
    throw;
  }
}

void finish_partial_file(MPI_Comm comm, hdf5_handle& file, const std::string& partial, bool& storage_failed) {
  hdf5_quiet_scope quiet;
  // Everything on disk before the close, so that a failure leaves the file open.
  std::optional<failure_record> failed;
  if (H5Fflush(file.get(), H5F_SCOPE_GLOBAL) < 0)
    failed = failure_record{failure::file, "cannot flush '" + partial + "'" + hdf5_reason()};
  raise_marking_storage_failure(comm, failed, storage_failed);
  if (file.close() < 0) failed = failure_record{failure::file, "cannot close '" + partial + "'" + hdf5_reason()};
  raise_if_any(comm, failed);
}

void rename_partial_file(MPI_Comm comm, const std::string& partial, const std::string& path) {
  std::optional<failure_record> failed;
  // The final path is checked again: it may have changed while the run wrote.
  if (rank_of(comm) == 0) {
    std::error_code error;
    try {
      require_replaceable(path);
      std::filesystem::rename(partial, path, error);
    } catch (const io_error& e) {
      failed = failure_record{e.kind(), e.what()};
    }
    if (error)
      failed = failure_record{failure::file, "cannot rename '" + partial + "' to '" + path + "': " + error.message()};
  }
  raise_if_any(comm, failed);  // also keeps every rank here until the rename is done
}

bool close_unfinished_file(MPI_Comm comm, hdf5_handle& file, const std::string& partial, bool storage_failed) {
  hdf5_quiet_scope quiet;
  int flushed = 0;
  if (!storage_failed) {
    flushed = H5Fflush(file.get(), H5F_SCOPE_GLOBAL) >= 0;
    MPI_Allreduce(MPI_IN_PLACE, &flushed, 1, MPI_INT, MPI_MIN, comm);
  }
  if (!flushed) {
    std::error_code error;
    if (rank_of(comm) == 0) std::filesystem::resize_file(partial, 0, error);
    MPI_Barrier(comm);
  }
  file.close();
  return flushed;
}

}  // namespace flecsi_lite::io
