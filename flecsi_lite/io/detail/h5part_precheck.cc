// The metadata of an HDF5 file listed and checked in a forked child (see h5part_precheck.hh).
#include "flecsi_lite/io/detail/h5part_precheck.hh"

#include "flecsi_lite/io/detail/hdf5_attributes.hh"
#include "flecsi_lite/io/detail/hdf5_errors.hh"
#include "flecsi_lite/io/detail/hdf5_handle.hh"
#include "flecsi_lite/io/io_error.hh"

#include <hdf5.h>
#include <poll.h>
#include <signal.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <chrono>
#include <cstring>
#include <vector>

namespace flecsi_lite::io::h5part {

namespace {
struct link_entry {
  std::string name;
  bool hard = false;
};

herr_t collect_link(hid_t, const char* name, const H5L_info_t* info, void* links) {
  static_cast<std::vector<link_entry>*>(links)->push_back({name, info->type == H5L_TYPE_HARD});
  return 0;
}

// The walk of the child: the first HDF5 failure becomes `problem`; names go to `listing`.
class walker {
 public:
  explicit walker(std::string path) : path_(std::move(path)) {}
  metadata_check result;

  void walk_root(hid_t file) {
    std::vector<link_entry> links;
    if (!list(file, "the root group", links)) return;
    walk_attributes(file, "the root group");
    auto& root_datasets = result.listing.datasets[""];
    for (const auto& link : links) {
      auto object = open(file, link, link.name);
      if (!object) continue;
      const H5I_type_t kind = H5Iget_type(object.get());
      if (kind == H5I_GROUP) {
        result.listing.groups.push_back(link.name);
        walk_group(object.get(), link.name);
      } else if (kind == H5I_DATASET) {
        root_datasets.push_back(link.name);
        walk_dataset(object.get(), link.name);
      }
    }
  }

 private:
  void fail(const std::string& what) { fail_because(what + hdf5_reason()); }
  void fail_because(const std::string& why) {
    if (result.problem.empty()) result.problem = "'" + path_ + "' is corrupted: " + why;
  }

  bool list(hid_t group, const std::string& what, std::vector<link_entry>& links) {
    hsize_t position = 0;
    if (H5Literate(group, H5_INDEX_NAME, H5_ITER_INC, &position, collect_link, &links) >= 0) return true;
    fail("cannot list the links of " + what);
    return false;
  }

  hdf5_handle open(hid_t group, const link_entry& link, const std::string& what) {
    auto object = object_handle(H5Oopen(group, link.name.c_str(), H5P_DEFAULT));
    // A soft or external link that leads nowhere is no damage of this file.
    if (!object && link.hard) fail("cannot open '" + what + "'");
    return object;
  }

  void walk_group(hid_t group, const std::string& name) {
    std::vector<link_entry> links;
    if (!list(group, "group '" + name + "'", links)) return;
    walk_attributes(group, "group '" + name + "'");
    auto& datasets = result.listing.datasets[name];
    for (const auto& link : links) {
      const std::string what = name + "/" + link.name;
      auto object = open(group, link, what);
      if (object && H5Iget_type(object.get()) == H5I_DATASET) {
        datasets.push_back(link.name);
        walk_dataset(object.get(), what);
      }
    }
  }

  void walk_dataset(hid_t dataset, const std::string& what) {
    auto space = dataspace_handle(H5Dget_space(dataset));
    auto type = datatype_handle(H5Dget_type(dataset));
    auto creation = property_list_handle(H5Dget_create_plist(dataset));
    if (!space || !type || !creation) return fail("cannot inspect dataset '" + what + "'");
    hsize_t extent[H5S_MAX_RANK];
    if (H5Sget_simple_extent_ndims(space.get()) <= H5S_MAX_RANK)
      H5Sget_simple_extent_dims(space.get(), extent, nullptr);
    H5Tget_size(type.get()), H5Tget_class(type.get());
    H5Pget_nfilters(creation.get()), H5Pget_layout(creation.get());
    H5Dget_storage_size(dataset);
    walk_attributes(dataset, "dataset '" + what + "'");
  }

  void walk_attributes(hid_t object, const std::string& what) {
    try {
      for (const auto& name : attribute_names(object)) {
        try {
          read_attribute(object, name, "attribute '" + name + "' of " + what);
        } catch (const element_type_error&) {  // a kind of value the reader refuses if asked for it
        }
      }
    } catch (const io_error& e) {
      fail_because(std::string(e.what()) + " of " + what);
    }
  }

  std::string path_;
};

// The child's report through the pipe: the problem, then the listing.
void write_all(int fd, const std::string& bytes) {
  for (std::size_t done = 0; done < bytes.size();) {
    const ssize_t n = write(fd, bytes.data() + done, bytes.size() - done);
    if (n <= 0) return;
    done += static_cast<std::size_t>(n);
  }
}

[[noreturn]] void run_child(const std::string& path, int fd) {
  // The child makes no MPI call and skips every exit handler of the parent's libraries; it
  // dies of its signal quietly (Open MPI's handler would print a backtrace).
  for (int signal_number : {SIGSEGV, SIGBUS, SIGABRT, SIGFPE, SIGILL}) signal(signal_number, SIG_DFL);
  hdf5_quiet_scope quiet;
  // The reader's format bounds (hdf5_parallel.cc), with the serial driver.
  auto access = property_list_handle(H5Pcreate(H5P_FILE_ACCESS));
  H5Pset_libver_bounds(access.get(), H5F_LIBVER_V18, H5F_LIBVER_LATEST);
  auto file = file_handle(H5Fopen(path.c_str(), H5F_ACC_RDONLY, access.get()));
  walker first(path), second(path);
  if (!file) {
    first.result.problem = "'" + path + "' is truncated or corrupted: HDF5 cannot open it" + hdf5_reason();
  } else {
    first.walk_root(file.get());
    // Twice: a corrupted heap can crash only once an earlier visit's error has left damaged
    // entries in HDF5's metadata cache (the job reads groups several times).
    second.walk_root(file.get());
  }
  const std::string problem = first.result.problem.empty() ? second.result.problem : first.result.problem;
  write_all(fd, std::to_string(problem.size()) + ':' + problem + encode(first.result.listing));
  _exit(0);
}

// Everything the child writes, until it closes the pipe or the deadline passes.
bool read_report(int fd, std::chrono::steady_clock::time_point deadline, std::string& bytes) {
  char buffer[65536];
  for (;;) {
    const auto left =
      std::chrono::duration_cast<std::chrono::milliseconds>(deadline - std::chrono::steady_clock::now());
    if (left.count() <= 0) return false;
    pollfd wait_for{fd, POLLIN, 0};
    const int ready = poll(&wait_for, 1, static_cast<int>(std::min<long long>(left.count(), 1000)));
    if (ready < 0 && errno != EINTR) return true;
    if (ready <= 0) continue;
    const ssize_t n = read(fd, buffer, sizeof buffer);
    if (n < 0 && errno == EINTR) continue;
    if (n <= 0) return true;
    bytes.append(buffer, static_cast<std::size_t>(n));
  }
}
}  // namespace

metadata_check check_metadata(const std::string& path, double seconds) {
  int pipe_ends[2];
  if (pipe(pipe_ends) != 0) return {"cannot check '" + path + "': no pipe (" + std::strerror(errno) + ")", {}};
  const pid_t child = fork();
  if (child < 0) {
    close(pipe_ends[0]), close(pipe_ends[1]);
    return {"cannot check '" + path + "': no process (" + std::strerror(errno) + ")", {}};
  }
  if (child == 0) {
    close(pipe_ends[0]);
    run_child(path, pipe_ends[1]);
  }
  close(pipe_ends[1]);
  std::string bytes;
  const auto deadline =
    std::chrono::steady_clock::now() +
    std::chrono::duration_cast<std::chrono::steady_clock::duration>(std::chrono::duration<double>(seconds));
  const bool ended = read_report(pipe_ends[0], deadline, bytes);
  close(pipe_ends[0]);
  int status = 0;
  if (!ended) kill(child, SIGKILL);
  waitpid(child, &status, 0);
  if (!ended)
    return {"'" + path + "' is corrupted: HDF5 did not finish reading its metadata within " +
              std::to_string(static_cast<long>(seconds)) + " s",
            {}};
  if (WIFSIGNALED(status))
    return {"'" + path + "' is corrupted: HDF5 crashed (" + std::string(strsignal(WTERMSIG(status))) +
              ") reading its metadata in a test process; the file cannot be read safely",
            {}};
  metadata_check check;
  try {
    const std::size_t colon = bytes.find(':');
    const std::size_t size = std::stoull(bytes.substr(0, colon));
    check.problem = bytes.substr(colon + 1, size);
    check.listing = decode_listing(bytes.substr(colon + 1 + size));
  } catch (const std::exception&) {
    check.problem = "cannot check '" + path + "': the test process ended without its report";
  }
  return check;
}

}  // namespace flecsi_lite::io::h5part
