// The frame every SPH app (sod, sedov, ...) shares, so that an app is its problem and its
// reports: the settings read from the parameters, initial particles from the problem, from an
// H5Part file or from a checkpoint, the H5Part output at a cadence, checkpoints, the statistics
// file, the particles, kernel and EOS in the start-up banner, and main() on the framework's app
// frame (flecsi_lite/app.hh). Restarts continue the output series and the statistics file; a run
// that stops before end_time (max_steps, wall_time_limit, stop_file) writes a checkpoint and
// prints the one command that resumes it.
//
//   struct my_run : sph::app_state<D> { my::problem problem; };
//   auto m = sph::make_app_control_model<my_run>({set_domain, create_particles});
//   m.action("finalize", "report", report);          // the app's own comparisons
//   return context.execute(m, state, check);         // under --control-model: no run, no check
//
// One concern a header, all in this folder:
//   app_state.hh          the run's state: the simulation plus its files, series and statistics
//   configure.hh          the parameters read into it; restart_free_keys; the resume command
//   initial_data.hh       particles from initial data or from a checkpoint (restart)
//   output_series.hh      the H5Part file and snapshots: opened, a step when due, closed
//   banner.hh             the start-up line on the particles, kernel and EOS
//   statistics_rows.hh    the statistics file's rows (statistics.hh: the file and its format)
//   run_limits.hh         max_steps, wall_time_limit and the stop file
//   checkpoints.hh        a checkpoint at its cadence and when the run stops early (restart.hh)
//   app_control_model.hh  all of them placed on the standard control model
//   app_main.hh           the app's definition and main()
#pragma once

#include "specialization/sph/instances.hh"
#include "specialization/sph/run/app_control_model.hh"
#include "specialization/sph/run/app_main.hh"
#include "specialization/sph/run/app_state.hh"
#include "specialization/sph/run/configure.hh"

#include "flecsi_lite/app.hh"

namespace flecsph::sph {

// Compiled in the library (instances_*.cc).
FLECSPH_SPH_APP_INSTANCES(extern, 1)
FLECSPH_SPH_APP_INSTANCES(extern, 2)
FLECSPH_SPH_APP_INSTANCES(extern, 3)

}  // namespace flecsph::sph
