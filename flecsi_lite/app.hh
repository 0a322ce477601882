// The app frame: main() with a parameter file, --set, --parameters-help, --control-model and
// exit statuses for every flecsi_lite program, and the file keys (output, checkpoints, restart).
#pragma once
#include "flecsi_lite/app/file_settings.hh"
#include "flecsi_lite/app/frame.hh"
