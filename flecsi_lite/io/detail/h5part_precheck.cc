// Crash check of an H5Part file's metadata in a forked child (see h5part_precheck.hh).
#include "flecsi_lite/io/detail/h5part_precheck.hh"

#include "flecsi_lite/io/detail/hdf5_attributes.hh"
#include "flecsi_lite/io/detail/hdf5_errors.hh"
#include "flecsi_lite/io/detail/hdf5_handle.hh"

#include <hdf5.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cstring>
#include <thread>
#include <vector>

namespace flecsi_lite::io::h5part {

namespace {
herr_t collect_link(hid_t, const char* name, const H5L_info_t*, void* names) {
  static_cast<std::vector<std::string>*>(names)->emplace_back(name);
  return 0;
}

void walk_attributes(hid_t object) {
  try {
    for (const auto& name : attribute_names(object)) read_attribute(object, name, name);
  } catch (const std::exception&) {  // an error, not a crash: the reader reports it
  }
}

void walk_dataset(hid_t dataset) {
  auto space = dataspace_handle(H5Dget_space(dataset));
  if (space) {
    hsize_t extent[H5S_MAX_RANK];
    if (H5Sget_simple_extent_ndims(space.get()) <= H5S_MAX_RANK)
      H5Sget_simple_extent_dims(space.get(), extent, nullptr);
  }
  auto type = datatype_handle(H5Dget_type(dataset));
  if (type) H5Tget_size(type.get()), H5Tget_class(type.get());
  auto creation = property_list_handle(H5Dget_create_plist(dataset));
  if (creation) H5Pget_nfilters(creation.get()), H5Pget_layout(creation.get());
  H5Dget_storage_size(dataset);
  walk_attributes(dataset);
}

// The same calls as the reader (links by name, H5Oopen, attributes), one group level deep as
// H5Part has, plus the datasets' own metadata.
void walk(hid_t group, int depth) {
  // Links first, attributes after, as the reader does: the order decides which of HDF5's error
  // paths a corrupted header takes.
  std::vector<std::string> links;
  hsize_t position = 0;
  const bool listed = H5Literate(group, H5_INDEX_NAME, H5_ITER_INC, &position, collect_link, &links) >= 0;
  walk_attributes(group);
  if (!listed) return;
  for (const auto& link : links) {
    auto object = object_handle(H5Oopen(group, link.c_str(), H5P_DEFAULT));
    if (!object) continue;
    const H5I_type_t kind = H5Iget_type(object.get());
    if (kind == H5I_GROUP && depth < 2) walk(object.get(), depth + 1);
    if (kind == H5I_DATASET) walk_dataset(object.get());
  }
}
}  // namespace

std::string metadata_crash_check(const std::string& path, double seconds) {
  const pid_t child = fork();
  if (child < 0) return "";  // no process to spare: the collective open goes unprotected
  if (child == 0) {
    // The child makes no MPI call and skips every exit handler of the parent's libraries; it
    // dies of its signal quietly (Open MPI's handler would print a backtrace).
    for (int signal_number : {SIGSEGV, SIGBUS, SIGABRT, SIGFPE, SIGILL}) signal(signal_number, SIG_DFL);
    hdf5_quiet_scope quiet;
    // The reader's format bounds (hdf5_parallel.cc), with the serial driver.
    auto access = property_list_handle(H5Pcreate(H5P_FILE_ACCESS));
    H5Pset_libver_bounds(access.get(), H5F_LIBVER_V18, H5F_LIBVER_LATEST);
    auto file = file_handle(H5Fopen(path.c_str(), H5F_ACC_RDONLY, access.get()));
    // Twice: the reader visits groups several times, and a corrupted heap can crash only once
    // an earlier visit's error has left damaged entries in HDF5's metadata cache.
    if (file) walk(file.get(), 0), walk(file.get(), 0);
    _exit(0);
  }
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::duration<double>(seconds);
  int status = 0;
  for (;;) {
    const pid_t done = waitpid(child, &status, WNOHANG);
    if (done == child) break;
    if (done < 0) return "";
    if (std::chrono::steady_clock::now() > deadline) {
      kill(child, SIGKILL);
      waitpid(child, &status, 0);
      return "'" + path + "' is corrupted: HDF5 did not finish reading its metadata within " +
             std::to_string(static_cast<long>(seconds)) + " s";
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  if (WIFSIGNALED(status))
    return "'" + path + "' is corrupted: HDF5 crashed (" + strsignal(WTERMSIG(status)) +
           ") reading its metadata in a test process; the file cannot be read safely";
  return "";
}

}  // namespace flecsi_lite::io::h5part
