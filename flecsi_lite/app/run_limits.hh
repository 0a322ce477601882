// When a run stops before its end time besides max_steps: a wall-time limit (key wall_time_limit)
// and a stop file (key stop_file), decided on rank 0 and broadcast, so every rank stops at one step.
#pragma once

#include "flecsi_lite/runtime/parameter_block.hh"

#include <chrono>
#include <string>

namespace flecsi_lite::app {

struct run_limits {
  double wall_time_limit = 0;  ///< seconds of wall time after which the run stops; 0: none
  /// "auto": `<output stem>.stop` (output_file's folder); empty: none. Created by the user (`touch`).
  std::string stop_file = "auto";
};

/// The keys wall_time_limit and stop_file.
runtime::parameter_block<run_limits> run_limit_parameters();

/// stop_file with "auto" resolved beside `output_file` (beside_output), for `program`.
std::string resolved_stop_file(const run_limits& limits, const std::string& output_file, const std::string& program);

/// The clock and the stop file of one run. check() is collective: rank 0 looks at the clock and
/// the file, every rank gets its verdict, so that all stop after the same step.
class stop_monitor {
 public:
  stop_monitor() = default;
  /// The clock runs from now.
  stop_monitor(double wall_time_limit, std::string stop_file);

  /// Why the run must stop now ("" to go on). A stop file found is removed when it is a regular
  /// file (nothing else is ever removed), so that the run resumed from the checkpoint does not
  /// stop at once. Collective.
  std::string check() const;
  const std::string& stop_file() const { return stop_file_; }
  double wall_time_limit() const { return wall_time_limit_; }

 private:
  double wall_time_limit_ = 0;
  std::string stop_file_;
  std::chrono::steady_clock::time_point started_ = std::chrono::steady_clock::now();
};

}  // namespace flecsi_lite::app
