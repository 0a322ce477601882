// The file keys of the app frame (file_settings.hh), declared once with their checks.
#include "flecsi_lite/app/file_settings.hh"

namespace flecsi_lite::app {

runtime::parameter_block<file_settings> file_parameters(const file_settings& defaults) {
  using runtime::parameter_error;
  runtime::parameter_block<file_settings> files(defaults);
  files.file("output_file", &file_settings::output_file, "H5Part output file (none: no output)");
  files.real("output_every", &file_settings::output_every, "simulation time between outputs (0: first and last step only)")
    .at_least(0);
  files.file("checkpoint_file", &file_settings::checkpoint_file,
             "checkpoint (H5Part) for restarts, replaced at each checkpoint");
  files.integer("checkpoint_every", &file_settings::checkpoint_every, "steps between checkpoints (0: none)").at_least(0);
  files.file("restart_file", &file_settings::restart_file,
             "continue the run saved in this checkpoint (none: start at t = 0)");
  files.file("initial_data", &file_settings::initial_data,
             "H5Part file of the initial particles (none: the problem's own)");
  files.integer("initial_data_step", &file_settings::initial_data_step, "Step#k of initial_data to read (-1: the last)")
    .at_least(-1);
  files.check([](const file_settings& f) {
    if (!f.restart_file.empty() && !f.initial_data.empty())
      throw parameter_error("restart_file and initial_data are both set: a restart continues "
                            "the checkpoint's particles; set only one of them");
    if (f.checkpoint_every > 0 && f.checkpoint_file.empty())
      throw parameter_error("checkpoint_every = " + std::to_string(f.checkpoint_every) +
                            " needs a checkpoint_file (it is none)");
  });
  return files;
}

} // namespace flecsi_lite::app
