// The app frame: main() with a parameter file, --set, --parameters-help, --control-model and
// exit statuses for every flecsi_lite program, the file keys (output, checkpoints, restart), the
// run limits (wall time, stop file) and the parameters a restart may change.
#pragma once
#include "flecsi_lite/app/check_options.hh"
#include "flecsi_lite/app/file_settings.hh"
#include "flecsi_lite/app/frame.hh"
#include "flecsi_lite/app/parameter_changes.hh"
#include "flecsi_lite/app/run_limits.hh"
