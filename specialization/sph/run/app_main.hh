// main() of an SPH app (app.hh, defined in app_main.cc): the app's definition (its name, help, problem
// keys, defaults, options and checks) on the framework's app frame (flecsi_lite/app.hh) with the
// SPH keys.
#pragma once

#include "specialization/sph/model/settings.hh"
#include "specialization/sph/run/app_state.hh"

#include "flecsi_lite/app.hh"
#include "flecsi_lite/runtime.hh"

#include <functional>
#include <string>
#include <vector>

namespace flecsph::sph {
/// An SPH app for the framework's frame (flecsi_lite/app.hh): its name and help, its problem's
/// keys, the defaults it chooses for the physics, run-control and file keys, its options and the run.
struct app_definition {
  std::string program;
  std::string summary;                                                              ///< first line of --help
  std::function<void(flecsi_lite::runtime::parameter_schema&)> declare_parameters;  ///< the problem's keys
  physics_settings physics_defaults;  ///< gamma, kernel, dissipation, ... of the problem
  run_settings run_defaults;          ///< end_time, progress_every, diagnostics_every of the problem
  io_settings file_defaults;          ///< output_file and checkpoint_file of the problem
  std::function<void(flecsi_lite::runtime::options&)> declare_options;  ///< the app's own options
  /// The app's checks, parsed at start-up (flecsi_lite/app/check_options.hh): run.checks().
  std::vector<flecsi_lite::app::check_option> checks;
  std::function<int(const flecsi_lite::app::run_context&)> run;
};

/// The frame's definition of `app`: its keys, then the physics, run-control and file keys.
flecsi_lite::app::definition frame_definition(const app_definition& app);

/// flecsi_lite::app::main of frame_definition(app): a parameter file, --set KEY=VALUE,
/// --parameters-help, --control-model, and the frame's exit statuses (0 run; 1 a check failed;
/// 2 bad parameters; 3 any other error, reported on rank 0 with what was wrong).
int app_main(int argc, char** argv, const app_definition& app);
}  // namespace flecsph::sph
