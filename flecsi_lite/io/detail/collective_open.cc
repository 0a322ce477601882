// Collective read-only open of an HDF5 file (see collective_open.hh).
#include "flecsi_lite/io/detail/collective_open.hh"

#include "flecsi_lite/io/collective_agreement.hh"
#include "flecsi_lite/io/detail/h5part_precheck.hh"
#include "flecsi_lite/io/detail/hdf5_errors.hh"
#include "flecsi_lite/io/detail/hdf5_parallel.hh"
#include "flecsi_lite/io/io_error.hh"
#include "flecsi_lite/io/output_path.hh"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>
#include <utility>

namespace flecsi_lite::io {

namespace {
// Rank 0's look at the file before HDF5 opens it, for a precise message.
metadata_listing check_readable_hdf5(const std::string& path, const std::string& kind) {
  std::error_code error;
  const auto status = std::filesystem::status(path, error);
  if (!std::filesystem::exists(status)) throw file_error("cannot open '" + path + "': no such file");
  if (std::filesystem::is_directory(status))
    throw file_error("cannot open '" + path + "': it is a directory, not " + kind);
  // Opening a fifo waits for a writer for ever (fuzz campaign, seed 7: restart_file = a fifo).
  if (!std::filesystem::is_regular_file(status))
    throw file_error("cannot open '" + path + "': it is not a regular file (a fifo, socket or device), not " + kind);
  std::ifstream probe(path, std::ios::binary);
  if (!probe) throw file_error("cannot read '" + path + "': " + std::strerror(errno));
  const htri_t is_hdf5 = H5Fis_hdf5(path.c_str());
  if (is_hdf5 == 0) throw file_error("'" + path + "' is not an HDF5 file (no HDF5 signature)");
  if (is_hdf5 < 0) throw file_error("cannot read '" + path + "'" + hdf5_reason());
  auto check = h5part::check_metadata(path);
  if (!check.problem.empty()) throw file_error(check.problem);
  return std::move(check.listing);
}
}  // namespace

opened_file open_for_reading_collectively(const std::string& path, MPI_Comm comm, const std::string& kind) {
  metadata_listing listing;
  agree(comm, [&] {
    if (rank_of(comm) == 0) listing = check_readable_hdf5(path, kind);
  });
  listing = broadcast_listing(listing, 0, comm);
  const std::string name = mpi_io_name(path);  // the same verdict on every rank
  auto access = mpio_file_access(comm);
  auto file = file_handle(H5Fopen(name.c_str(), H5F_ACC_RDONLY, access.get()));
  std::optional<failure_record> failed;
  if (!file)
    failed =
      failure_record{failure::file, "'" + path + "' is truncated or corrupted: HDF5 cannot open it" + hdf5_reason()};
  try {
    raise_if_any(comm, failed);
  } catch (...) {
    file.release();  // a parallel close on only the ranks that opened it would never return
    throw;
  }
  return {std::move(file), std::move(listing)};
}

}  // namespace flecsi_lite::io
