// The file keys of the app frame (file_settings.hh), declared once with their checks.
#include "flecsi_lite/app/file_settings.hh"

#include "flecsi_lite/io/output_path.hh"

#include <filesystem>
#include <utility>
#include <vector>

namespace flecsi_lite::app {

namespace {
using runtime::parameter_error;

// One file as the path it resolves to, so that "./a.h5part" and "a.h5part" are the same file.
std::string normalized(const std::string& path) {
  std::error_code error;
  const auto resolved = std::filesystem::weakly_canonical(std::filesystem::absolute(path), error);
  return error ? path : resolved.lexically_normal().string();
}

struct named_file {
  const char* key;
  const std::string& path;
};

// A file opened with MPI-IO (under its temporary name when written): checked at start-up, not
// found when the first checkpoint is written after hours.
void require_mpi_io_name(const char* key, const std::string& path) {
  if (const std::string problem = io::mpi_io_name_problem(path); !problem.empty())
    throw parameter_error(std::string(key) + ": " + problem);
}

// A file the run writes: it can be created where it is named, and what is there now may be replaced.
void require_writable(const named_file& file) {
  if (file.path.empty()) return;
  const std::string kind = io::non_regular_kind(file.path);
  if (!kind.empty())
    throw parameter_error(std::string(file.key) + " = '" + file.path + "' is " + kind +
                          ", not a regular file: it is never replaced; choose another path");
  const std::string reason = io::unwritable_folder_reason(file.path);
  if (!reason.empty())
    throw parameter_error(std::string(file.key) + " = '" + file.path + "' cannot be written: " + reason);
  require_mpi_io_name(file.key, file.path + ".partial");
}

// Two keys naming one file (names_same_file).
void require_distinct(const named_file& written, const named_file& other) {
  if (names_same_file(written.path, other.path))
    throw parameter_error(std::string(written.key) + " = '" + written.path + "' and " + other.key + " = '" +
                          other.path + "' name the same file (or its temporary '.partial'): writing " + written.key +
                          " would destroy it; give them different paths");
}
}  // namespace

bool names_same_file(const std::string& a, const std::string& b) {
  if (a.empty() || b.empty()) return false;
  const std::string x = normalized(a), y = normalized(b);
  if (x == y || x == y + ".partial" || y == x + ".partial") return true;
  // Two names of one existing file (a hard link, or a link the resolution above did not see).
  std::error_code error;
  return std::filesystem::equivalent(a, b, error) && !error;
}

runtime::parameter_block<file_settings> file_parameters(const file_settings& defaults) {
  runtime::parameter_block<file_settings> files(defaults);
  files.file("output_file", &file_settings::output_file, "H5Part output file (none: no output)");
  files
    .real("output_every", &file_settings::output_every, "simulation time between outputs (0: first and last step only)")
    .at_least(0);
  files.file("checkpoint_file", &file_settings::checkpoint_file,
             "checkpoint (H5Part) for restarts, replaced at each checkpoint");
  files.integer("checkpoint_every", &file_settings::checkpoint_every, "steps between checkpoints (0: none)")
    .at_least(0);
  files.file("restart_file", &file_settings::restart_file,
             "continue the run saved in this checkpoint (none: start at t = 0)");
  files.file("initial_data", &file_settings::initial_data,
             "H5Part file or SWIFT-format initial conditions (Header, PartType0) of the initial particles (none: the "
             "problem's own)");
  files.integer("initial_data_step", &file_settings::initial_data_step, "Step#k of initial_data to read (-1: the last)")
    .at_least(-1);
  files.check([](const file_settings& f) {
    const named_file output{"output_file", f.output_file}, checkpoint{"checkpoint_file", f.checkpoint_file},
      restart{"restart_file", f.restart_file}, initial{"initial_data", f.initial_data};
    // Checked at start-up, not when the file is first written after the run (or a checkpoint).
    require_writable(output);
    // Always, not only with checkpoint_every: a run that stops early (max_steps, wall_time_limit,
    // stop_file) writes its checkpoint there.
    require_writable(checkpoint);
    require_distinct(output, checkpoint);
    require_distinct(output, restart);
    require_distinct(output, initial);
    require_distinct(checkpoint, initial);
    for (const named_file& read : {restart, initial})
      if (!read.path.empty()) require_mpi_io_name(read.key, read.path);
    // checkpoint_file = restart_file is allowed: the checkpoint is read whole at start-up, and a
    // new one replaces it only by an atomic rename once complete (a run continued in chunks).
    if (!f.restart_file.empty() && !f.initial_data.empty())
      throw parameter_error(
        "restart_file and initial_data are both set: a restart continues "
        "the checkpoint's particles; set only one of them");
    if (f.checkpoint_every > 0 && f.checkpoint_file.empty())
      throw parameter_error("checkpoint_every = " + std::to_string(f.checkpoint_every) +
                            " needs a checkpoint_file (it is none)");
  });
  return files;
}

}  // namespace flecsi_lite::app
