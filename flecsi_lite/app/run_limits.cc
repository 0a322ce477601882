// The wall-time limit and the stop file of a run (run_limits.hh).
#include "flecsi_lite/app/run_limits.hh"

#include "flecsi_lite/app/frame.hh"
#include "flecsi_lite/runtime/context.hh"

#include <mpi.h>

#include <filesystem>
#include <sstream>
#include <utility>
#include <vector>

namespace flecsi_lite::app {

runtime::parameter_block<run_limits> run_limit_parameters() {
  runtime::parameter_block<run_limits> block;
  block
    .real("wall_time_limit", &run_limits::wall_time_limit,
          "wall seconds after which the run checkpoints and stops (0: none); leave room for the checkpoint")
    .at_least(0);
  block.file("stop_file", &run_limits::stop_file,
             "when this file exists, the run checkpoints and stops (auto: <output stem>.stop; none: off)");
  return block;
}

std::string resolved_stop_file(const run_limits& limits, const std::string& output_file, const std::string& program) {
  return limits.stop_file == "auto" ? beside_output(output_file, program, ".stop") : limits.stop_file;
}

stop_monitor::stop_monitor(double wall_time_limit, std::string stop_file)
    : wall_time_limit_(wall_time_limit), stop_file_(std::move(stop_file)) {}

std::string stop_monitor::check() const {
  // Rank 0's clock and file system decide; the reason travels as text to every rank.
  std::string reason;
  if (runtime::rank() == 0) {
    const double elapsed = std::chrono::duration<double>(std::chrono::steady_clock::now() - started_).count();
    std::error_code error;
    if (wall_time_limit_ > 0 && elapsed >= wall_time_limit_) {
      std::ostringstream text;
      text << "wall_time_limit = " << wall_time_limit_ << " s reached (" << elapsed << " s)";
      reason = text.str();
    } else if (const auto status = std::filesystem::symlink_status(stop_file_, error);
               !stop_file_.empty() && std::filesystem::exists(status)) {
      // Only a regular file, the user's `touch`, is removed: never a folder, a device or a link.
      const bool regular = std::filesystem::is_regular_file(status);
      if (regular) std::filesystem::remove(stop_file_, error);
      reason = "stop file '" + stop_file_ + "' found" +
               (!regular ? " (not removed: not a regular file)"
                : error  ? ""
                         : " (removed)");
    }
  }
  int length = static_cast<int>(reason.size());
  MPI_Bcast(&length, 1, MPI_INT, 0, runtime::communicator());
  std::vector<char> text(reason.begin(), reason.end());
  text.resize(static_cast<std::size_t>(length));
  if (length > 0) MPI_Bcast(text.data(), length, MPI_CHAR, 0, runtime::communicator());
  return std::string(text.begin(), text.end());
}

}  // namespace flecsi_lite::app
