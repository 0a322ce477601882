// Checks of the paths writers replace (see output_path.hh), on std::filesystem and access(2).
#include "flecsi_lite/io/output_path.hh"

#include "flecsi_lite/io/io_error.hh"

#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>

namespace flecsi_lite::io {

namespace fs = std::filesystem;

std::string non_regular_kind(const std::string& path) {
  std::error_code error;
  const fs::file_status status = fs::symlink_status(path, error);  // the link itself, not its target
  switch (status.type()) {
    case fs::file_type::not_found:
    case fs::file_type::none:
    case fs::file_type::regular:
      return "";
    case fs::file_type::directory:
      return "a directory";
    case fs::file_type::symlink:
      return "a symbolic link";
    case fs::file_type::character:
      return "a character device";
    case fs::file_type::block:
      return "a block device";
    case fs::file_type::fifo:
      return "a fifo";
    case fs::file_type::socket:
      return "a socket";
    default:
      return "not a regular file";
  }
}

namespace {
std::string named(const std::string& path, const std::string& role) {
  return (role.empty() ? "" : role + " ") + "'" + path + "'";
}
}  // namespace

void require_replaceable(const std::string& path, const std::string& role) {
  const std::string kind = non_regular_kind(path);
  if (!kind.empty())
    throw file_error(named(path, role) + " exists and is " + kind +
                     ", not a regular file: it is never replaced; choose another path");
}

std::string unwritable_folder_reason(const std::string& path) {
  fs::path folder = fs::path(path).parent_path();
  if (folder.empty()) folder = ".";
  std::error_code error;
  const fs::file_status status = fs::status(folder, error);
  if (status.type() == fs::file_type::not_found) return "its folder '" + folder.string() + "' does not exist";
  if (status.type() != fs::file_type::directory) return "'" + folder.string() + "' is not a folder";
  // Creating the temporary file needs write and search permission on the folder.
  if (::access(folder.c_str(), W_OK | X_OK) != 0) return "its folder '" + folder.string() + "' is not writable";
  return "";
}

void require_writable_folder(const std::string& path, const std::string& role) {
  const std::string reason = unwritable_folder_reason(path);
  if (!reason.empty()) throw file_error("cannot write " + named(path, role) + ": " + reason);
}

namespace {
std::string shorter_name(const std::string& path) {
  if (path.size() <= longest_mpi_io_name) return path;
  std::error_code error;
  const std::string relative = std::filesystem::relative(path, error).string();
  return !error && !relative.empty() && relative.size() < path.size() ? relative : path;
}
}  // namespace

std::string mpi_io_name_problem(const std::string& path) {
  // Open MPI's "sm" component maps `<session folder>/<file name>_cid-<n>-<pid>.sm`: one name of
  // at most 255 characters.
  const std::size_t file_name = std::filesystem::path(path).filename().string().size();
  if (file_name > longest_mpi_io_file_name)
    return "'" + path + "' has a file name of " + std::to_string(file_name) +
           " characters: Open MPI's MPI-IO cannot open names longer than " + std::to_string(longest_mpi_io_file_name) +
           "; choose a shorter name";
  const std::string name = shorter_name(path);
  if (name.size() <= longest_mpi_io_name) return "";
  return "'" + path + "' is " + std::to_string(path.size()) + " characters long (" + std::to_string(name.size()) +
         " relative to the working folder): Open MPI's MPI-IO aborts on names longer than " +
         std::to_string(longest_mpi_io_name) + "; choose a shorter path (or run from a folder nearer to it)";
}

std::string mpi_io_name(const std::string& path, const std::string& role) {
  if (const std::string problem = mpi_io_name_problem(path); !problem.empty())
    throw file_error("cannot open " + (role.empty() ? std::string("the file") : "the " + role) + " " + problem);
  return shorter_name(path);
}

void write_text_file_aside(const std::string& path, const std::string& text, const std::string& role) {
  const std::string partial = path + ".partial";
  require_replaceable(path, role);
  require_replaceable(partial, "temporary file");
  std::ofstream out(partial, std::ios::trunc);
  out << text;
  // close() reports what flush() may not (a full disk seen only when the data reach it).
  out.close();
  if (!out) throw file_error("cannot write " + named(partial, "the " + role + " temporary file"));
}

void commit_text_file(const std::string& path, const std::string& role) {
  const std::string partial = path + ".partial";
  if (std::rename(partial.c_str(), path.c_str()) != 0)
    throw file_error("cannot rename '" + partial + "' to " + named(path, "the " + role));
}

void write_text_file(const std::string& path, const std::string& text, const std::string& role) {
  write_text_file_aside(path, text, role);
  commit_text_file(path, role);
}

}  // namespace flecsi_lite::io
