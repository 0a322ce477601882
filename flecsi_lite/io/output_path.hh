// Paths a writer may replace: an output, checkpoint or export is written under a temporary name
// and renamed over its final path, which must therefore be absent or a regular file (a rename
// would otherwise replace a device, a directory entry, a symbolic link or a fifo by a file).
//
//   io::require_replaceable("run.h5part");  // throws file_error when it is, e.g., a directory
//   io::require_writable_folder("out/run.h5part");   // its folder exists and can be written
#pragma once

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

}  // namespace flecsi_lite::io
