// The state of an SPH app's run (app.hh): the simulation plus its files, output series,
// statistics, run limits and the description its files carry; every piece of the run frame
// (configure.hh, output_series.hh, initial_data.hh, banner.hh, statistics_rows.hh,
// run_limits.hh, checkpoints.hh) reads and writes it.
#pragma once

#include "specialization/sph/files/snapshot_output.hh"
#include "specialization/sph/files/snapshot_settings.hh"
#include "specialization/sph/model/simulation.hh"
#include "specialization/sph/run/statistics.hh"

#include "flecsi_lite/app.hh"
#include "flecsi_lite/io.hh"

#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace flecsph::sph {

/// Files a run reads and writes (the file keys of the app frame); an empty name is "none".
using io_settings = flecsi_lite::app::file_settings;

/// A run of an app: the simulation plus its files.
template<int D>
struct app_state : simulation<D> {
  std::string program;          ///< the app's name, in messages and files
  std::string parameters_text;  ///< the resolved parameters, stored in every file
  io_settings files;
  double next_output = 0;  ///< simulation time of the next output
  std::unique_ptr<flecsi_lite::io::h5part_writer> writer;
  snapshot_settings output_keys;                  ///< output_format and the unit system
  std::unique_ptr<snapshot_series<D>> snapshots;  ///< with output_format snapshots or both
  /// Root attributes of the output that describe the problem (gamma, initial states, ...).
  flecsi_lite::io::run_state description;
  statistics_settings statistics_keys;  ///< statistics_file resolved ("auto" replaced; empty: none)
  statistics_log statistics;
  double statistics_dt = 0;  ///< the step about to be taken: the dt of the next row
  /// Columns an app appends to the statistics file, and their values at a row (called on every
  /// rank, so it may reduce); none by default.
  std::vector<statistics_column> extra_statistics_columns;
  std::function<std::vector<double>()> extra_statistics;
  /// The banner's equation of state, for an app whose pressure is not physics.eos's (the fluid
  /// app's Tait liquid); empty: physics.eos's name.
  std::string equation_of_state;
  flecsi_lite::app::stop_monitor stop;  ///< wall_time_limit and stop_file
  std::string stop_reason;              ///< why the run stopped before end_time ("": it did not)
  std::string allowed_changes;          ///< allow_parameter_changes
  std::string resume_command;           ///< this run's command line, to print with restart_file
  /// Whether the output was due at this step by its cadence (not only as the run's last step): a
  /// restart from this step keeps the step in the series only then.
  bool output_due = false;
  /// Called by the frame (run_context::execute) once the run and its checks have passed: only
  /// then do the output, complete since "finalize", and the statistics file replace earlier
  /// files of their names, and are the snapshots an earlier run left beyond this run's series
  /// removed.
  void commit_outputs() {
    if (writer) writer->commit();
    statistics.commit();
    if (snapshots) snapshots->remove_stale_snapshots();
  }
};

}  // namespace flecsph::sph
