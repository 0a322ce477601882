// The output series of an SPH run (app.hh): the H5Part file and the snapshots opened at the start
// (a restart continues the series of the run it continues), a step written when the cadence
// (output_every) says so or at the run's last step, and the files closed at "finalize".
#pragma once

#include "specialization/sph/files/particle_output.hh"
#include "specialization/sph/files/snapshot_layout.hh"
#include "specialization/sph/files/snapshot_output.hh"
#include "specialization/sph/files/snapshot_settings.hh"
#include "specialization/sph/run/app_state.hh"

#include "flecsi_lite/io.hh"
#include "flecsi_lite/runtime.hh"

#include <cstdint>
#include <memory>
#include <string>

namespace flecsph::sph {
namespace detail {
/// The output of this step when it is due by the cadence (output_every) or the run's last; only
/// a due one moves the cadence on, so that a run stopped early and resumed keeps the cadence.
template<int D>
void write_output_step(app_state<D>& s) {
  s.output_due = s.time >= s.next_output;
  if (!s.output_due && !s.finished) return;
  complete_deferred_fields(s);  // every particle's phi (gravity.hh)
  if (s.writer) write_particles(*s.writer, s);
  if (s.snapshots) s.snapshots->write(s);
  if (s.output_due) s.next_output = s.files.output_every > 0 ? s.time + s.files.output_every : s.run.end_time;
}

/// A new run starts the series with its first step. A restart at step N continues the series of
/// the run it continues: the writer starts from a copy of output_file (or the .partial an
/// interrupted run left), drops its steps after N (and N itself when that was written only as an
/// early stop's last step), and writes on; the copy replaces output_file when the run succeeds.
/// Without such a file, a new series starts with the restart step.
template<int D>
void open_output(app_state<D>& s) {
  if (s.files.output_file.empty()) return;
  if (writes_snapshots(s.output_keys)) {
    s.snapshots = std::make_unique<snapshot_series<D>>(s.files.output_file,
                                                       snapshot_run{s.program, s.parameters_text, s.output_keys.units});
    if (s.restarted) s.snapshots->continue_series(s.time, s.output_due);
    // A restart whose series has nothing before its step opens it with that step.
    if (s.restarted && s.snapshots->written() == 0) s.snapshots->write(s);
  }
  if (!writes_h5part(s.output_keys)) {
    if (!s.restarted) write_output_step(s);
    return;
  }
  using writer = flecsi_lite::io::h5part_writer;
  s.writer = std::make_unique<writer>(s.files.output_file, flecsi_lite::runtime::communicator(),
                                      s.restarted ? writer::mode::append : writer::mode::create);
  std::int64_t dropped = 0;
  if (s.restarted) dropped = s.writer->drop_steps_from(s.output_due ? s.step + 1 : s.step);
  s.writer->describe_run({s.program, s.parameters_text, D});
  s.writer->set_attribute("gamma", s.physics.eos.ideal.gamma);
  s.writer->set_attribute("ranks", static_cast<std::int64_t>(flecsi_lite::runtime::size()));
  for (const auto& [name, value] : s.description) s.writer->set_attribute(name, value);
  for (const auto& [name, value] : h5part_unit_attributes<D>(s.output_keys.units, s))
    s.writer->set_attribute(name, value);
  if (!s.restarted) return write_output_step(s);
  if (s.writer->steps_written() == 0) {
    write_particles(*s.writer, s);  // the restart step opens a new series; the cadence stays the checkpoint's
    return;
  }
  flecsi_lite::log::info() << s.program << ": continuing the output series of '" << s.files.output_file << "' after "
                           << s.writer->steps_written() << " steps (to step " << s.writer->last_iteration() << ")"
                           << (dropped ? ", " + std::to_string(dropped) + " later steps dropped" : std::string());
}

/// At "finalize": the output closed under its temporary name (commit_outputs renames it after
/// the app's checks) and what was written, on the log.
template<int D>
void close_output(app_state<D>& s) {
  if (s.snapshots)
    flecsi_lite::log::info() << s.program << ": " << s.snapshots->written() << " snapshots indexed in "
                             << s.snapshots->index_path();
  if (!s.writer) return;
  s.writer->finish();  // renamed by commit_outputs(), after the app's checks
  flecsi_lite::log::info() << s.program << ": wrote " << s.writer->steps_written() << " steps to "
                           << s.files.output_file;
}
}  // namespace detail
}  // namespace flecsph::sph
