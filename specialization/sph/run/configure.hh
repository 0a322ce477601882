// An SPH app's run configured from its parameters (app.hh): the physics, run-control, statistics,
// output and file keys read into the run's state, the command line that resumes it, and the keys
// a restart may change (restart_free_keys: add a key there when a restart may set it otherwise).
#pragma once

#include "specialization/sph/files/snapshot_output.hh"
#include "specialization/sph/files/snapshot_settings.hh"
#include "specialization/sph/model/settings.hh"
#include "specialization/sph/run/app_state.hh"
#include "specialization/sph/run/statistics.hh"

#include "flecsi_lite/app.hh"
#include "flecsi_lite/runtime.hh"

#include <set>
#include <string>
#include <utility>
#include <vector>

namespace flecsph::sph {

/// The keys a restart may set otherwise than its checkpoint without allow_parameter_changes:
/// the frame's (files, run limits, ...) and the SPH run-control and statistics keys. Every other
/// key (kernel, EOS, gamma, the problem's layout, ...) changes the solution.
inline std::set<std::string> restart_free_keys() {
  auto keys = flecsi_lite::app::frame_free_keys();
  for (const char* key :
       {"end_time", "max_steps", "progress_every", "diagnostics_every", "statistics_file", "statistics_every"})
    keys.insert(key);
  return keys;
}

/// The command line of this run as a shell would take it again (without any restart_file).
inline std::string command_line(const flecsi_lite::app::run_context& run) {
  const auto quoted = [](const std::string& word) {
    if (word.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_-+=.,/:@%") ==
        std::string::npos)
      return word;
    std::string text = "'";
    for (const char c : word) text += c == '\'' ? std::string("'\\''") : std::string(1, c);
    return text + "'";
  };
  std::string line = run.program();
  if (const auto file = run.options().get("parameters"); !file.empty()) line += " " + quoted(file);
  for (const auto& assignment : run.options().all("set"))
    if (assignment.compare(0, 13, "restart_file=") != 0) line += " --set " + quoted(assignment);
  return line;
}

/// Reads the physics, run-control, statistics and file keys into `s`; the program's name from the
/// frame. A statistics_file named like another file of the run is a parameter_error.
template<int D>
void configure(app_state<D>& s, const flecsi_lite::app::run_context& run) {
  const auto& p = run.parameters();
  s.program = run.program();
  s.physics = physics_parameters().read(p);
  s.run = run_parameters().read(p);
  s.files = flecsi_lite::app::file_parameters().read(p);
  s.parameters_text = p.resolved_text();
  s.statistics_keys = statistics_parameters().read(p);
  s.output_keys = snapshot_parameters().read(p);
  const auto limits = flecsi_lite::app::run_limit_parameters().read(p);
  s.stop = {limits.wall_time_limit, flecsi_lite::app::resolved_stop_file(limits, s.files.output_file, s.program)};
  s.allowed_changes = flecsi_lite::app::restart_parameters().read(p).allow_parameter_changes;
  s.resume_command = command_line(run);
  if (s.statistics_keys.file == "auto")
    s.statistics_keys.file = flecsi_lite::app::beside_output(s.files.output_file, s.program, ".statistics.txt");
  namespace app = flecsi_lite::app;
  app::check_distinct_file("statistics_file", s.statistics_keys.file,
                           {{"output_file", s.files.output_file},
                            {"checkpoint_file", s.files.checkpoint_file},
                            {"restart_file", s.files.restart_file},
                            {"initial_data", s.files.initial_data},
                            {"used_parameters_file", app::used_parameters_file(s.program, p)}});
  if (!writes_snapshots(s.output_keys) || s.files.output_file.empty()) return;
  for (const auto& [key, path] :
       std::vector<std::pair<std::string, std::string>>{{"checkpoint_file", s.files.checkpoint_file},
                                                        {"restart_file", s.files.restart_file},
                                                        {"initial_data", s.files.initial_data},
                                                        {"statistics_file", s.statistics_keys.file}})
    if (names_snapshot_file(path, s.files.output_file, s.program))
      throw flecsi_lite::runtime::parameter_error(
        key + " = '" + path + "' is a snapshot or the index of output_file = '" + s.files.output_file +
        "' (output_format = " + std::string(output_format_names().name(s.output_keys.format)) +
        "): writing the snapshots would destroy it; give it another name");
}

}  // namespace flecsph::sph
