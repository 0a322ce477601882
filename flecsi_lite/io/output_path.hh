// Paths a writer may replace: an output, checkpoint or export is written under a temporary name
// and renamed over its final path, which must therefore be absent or a regular file (a rename
// would otherwise replace a device, a directory entry, a symbolic link or a fifo by a file).
//
//   io::require_replaceable("run.h5part");  // throws file_error when it is, e.g., a directory
//   io::require_writable_folder("out/run.h5part");   // its folder exists and can be written
#pragma once

#include <cstddef>
#include <string>

namespace flecsi_lite::io {

/// What `path` is when it exists but is not a regular file ("a directory", "a symbolic link",
/// "a character device", "a block device", "a fifo", "a socket", "not a regular file"); empty when
/// it is absent or a regular file. A symbolic link is reported as one, whatever it points to.
std::string non_regular_kind(const std::string& path);

/// Throws file_error naming `path` (and `role`, e.g. "output", when not empty) when `path`
/// exists and is not a regular file. Local: no communication.
void require_replaceable(const std::string& path, const std::string& role = "");

/// The reason why a file cannot be created at `path` (its folder is missing, is not a folder or
/// cannot be written), empty when it can. Local: no communication.
std::string unwritable_folder_reason(const std::string& path);

/// Throws file_error with unwritable_folder_reason(path) when it is not empty.
void require_writable_folder(const std::string& path, const std::string& role = "");

/// Writes `text` to `<path>.partial` and renames it over `path`, so that a crash never leaves a
/// half-written file under `path`; neither may exist as anything but a regular file
/// (require_replaceable). Throws file_error naming `role` (e.g. "statistics_file"). Local.
void write_text_file(const std::string& path, const std::string& text, const std::string& role);

/// The longest name MPI_File_open may be given: Open MPI 4's shared-file-pointer component
/// "lockedfile" formats `<name>.locktest.<rank>` into a 256-byte buffer while the components are
/// selected, at every open, and a longer name aborts the program ("buffer overflow detected").
inline constexpr std::size_t longest_mpi_io_name = 256 - 1 - 10 - 10;
/// The longest file name (the last part of the path) it may be given: its "sm" component maps a
/// file `<file name>_cid-<n>-<pid>.sm` (at most 255 characters) and fails beyond.
inline constexpr std::size_t longest_mpi_io_file_name = 255 - 22;

/// The name under which `path` is opened with MPI-IO: `path` itself, or when it is longer than
/// longest_mpi_io_name the same file relative to the working folder if that is short enough.
/// Throws file_error (naming `role`, e.g. "output_file", when not empty) when neither is.
std::string mpi_io_name(const std::string& path, const std::string& role = "");

/// Why `path` cannot be opened with MPI-IO (mpi_io_name), empty when it can. Local.
std::string mpi_io_name_problem(const std::string& path);

/// The two halves of write_text_file, for a file that replaces an earlier one only when the run
/// that writes it succeeds: write_text_file_aside writes `<path>.partial` (the same checks),
/// commit_text_file renames it over `path`. Both throw file_error naming `role`. Local.
void write_text_file_aside(const std::string& path, const std::string& text, const std::string& role);
void commit_text_file(const std::string& path, const std::string& role);

}  // namespace flecsi_lite::io
