// The frame every SPH app (sod, sedov, ...) shares, so that an app is its problem and its
// reports: the settings read from the parameters, initial particles from the problem, from an
// H5Part file or from a checkpoint, the H5Part output at a cadence, checkpoints, the statistics
// file (statistics.hh), the particles, kernel and EOS in the start-up banner, and main() on the
// framework's app frame (flecsi_lite/app.hh). Restarts continue the output series and the
// statistics file; a run that stops before end_time (max_steps, wall_time_limit, stop_file)
// writes a checkpoint and prints the one command that resumes it.
//
//   struct my_run : sph::app_state<D> { my::problem problem; };
//   auto m = sph::make_app_control_model<my_run>({set_domain, create_particles});
//   m.action("finalize", "report", report);          // the app's own comparisons
//   return context.execute(m, state, check);         // under --control-model: no run, no check
#pragma once

#include "specialization/sph/files/particle_input.hh"
#include "specialization/sph/files/particle_output.hh"
#include "specialization/sph/files/snapshot_output.hh"
#include "specialization/sph/files/snapshot_settings.hh"
#include "specialization/sph/files/swift_initial_data.hh"
#include "specialization/sph/instances.hh"
#include "specialization/sph/run/restart.hh"
#include "specialization/sph/run/statistics.hh"
#include "specialization/sph/step/driver.hh"
#include "specialization/sph/step/gravity.hh"

#include "flecsi_lite/app.hh"
#include "flecsi_lite/control.hh"
#include "flecsi_lite/io.hh"
#include "flecsi_lite/runtime.hh"

#include <cstdint>
#include <cstdlib>
#include <functional>
#include <memory>
#include <optional>
#include <set>
#include <sstream>
#include <string>
#include <utility>
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

/// What an app adds to the standard model: the domain (box and periodic axes of
/// s.tree_settings) and, unless the particles come from a file, the particles themselves.
template<class State>
struct app_problem {
  std::function<void(State&)> set_domain;
  std::function<void(State&)> create_particles;
};

namespace detail {
/// The output of this step when it is due by the cadence (output_every) or the run's last; only
/// a due one moves the cadence on, so that a run stopped early and resumed keeps the cadence.
template<int D>
void write_output_step(app_state<D>& s) {
  s.output_due = s.time >= s.next_output;
  if (!s.output_due && !s.finished) return;
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
  for (const auto& [name, value] : h5part_unit_attributes<D>(s.output_keys.units, s.physics.gravity.enabled))
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

/// initial_data: an H5Part file (its step initial_data_step) or SWIFT-format initial conditions
/// (a file with the groups Header and PartType0, swift_initial_data.hh).
template<int D>
void read_initial_particles(app_state<D>& s) {
  const std::string& path = s.files.initial_data;
  if (flecsi_lite::io::gadget_reader::has_gadget_layout(path)) {
    if (s.files.initial_data_step != -1)
      throw flecsi_lite::runtime::parameter_error("initial_data_step = " + std::to_string(s.files.initial_data_step) +
                                                  " chooses a step of an H5Part file, "
                                                  "but initial_data = '" +
                                                  path +
                                                  "' holds SWIFT-format initial conditions (one set of particles): "
                                                  "remove initial_data_step");
    const auto count = read_swift_initial_data<D>(s, path, s.output_keys.units);
    flecsi_lite::log::info() << s.program << ": " << count << " initial particles from '" << path
                             << "' (SWIFT-format initial conditions)";
    return;
  }
  const flecsi_lite::io::h5part_reader in(path);
  const auto step = read_particles(s, in, s.files.initial_data_step);
  flecsi_lite::log::info() << s.program << ": " << in.particle_count(step) << " initial particles from "
                           << describe_input_step(in, step);
}

/// The checkpoint's particles, clock and output cadence; its program and dimension must be this
/// run's, its parameters too but for the free keys (restart_free_keys) and allow_parameter_changes.
template<int D>
void restart(app_state<D>& s) {
  namespace io = flecsi_lite::io;
  const std::string& path = s.files.restart_file;
  const auto state = read_restart_checkpoint(s, path, {{"program", s.program}});  // program, dimension first
  const auto& written = checkpoint_entry(state, "parameters", path);
  const auto written_text = io::attribute_as<std::string>(written, "run state 'parameters'");
  flecsi_lite::app::require_same_parameters(path, written_text, s.parameters_text, restart_free_keys(),
                                            s.allowed_changes);
  // Global steps: dt = min(criteria, end_time - time) of the writing run, whose end_time it stores.
  const auto written_values = flecsi_lite::app::parameter_values(written_text);
  if (const auto end = written_values.find("end_time"); end != written_values.end()) {
    char* rest = nullptr;
    const double written_end_time = std::strtod(end->second.c_str(), &rest);
    if (rest != end->second.c_str() && !s.physics.individual_time_steps())
      detail::check_step_left(path, s.time, s.dt, written_end_time);
  }
  s.next_output = io::attribute_as<double>(checkpoint_entry(state, "next_output", path), "run state 'next_output'");
  s.output_due = io::attribute_as<std::int64_t>(checkpoint_entry(state, "output_due", path), "run state 'output_due'");
  flecsi_lite::log::info() << s.program << ": restarting at step " << s.step << ", t = " << s.time << " from '" << path
                           << "'";
}

inline std::uint64_t rank_value(std::uint64_t value) { return value; }

inline std::uint64_t fluid_count(ro<particle_kind> kind) {
  std::uint64_t count = 0;
  for (std::size_t a = 0; a < kind.size(); ++a) count += kind(a) == particle_kind::fluid;
  return count;
}

/// The banner's SPH line: the particles as created (a lattice may hold fewer than asked for),
/// per rank once distributed, the kernel and the equation of state.
template<int D>
void describe_particles(app_state<D>& s) {
  using flecsi_lite::reduce;
  namespace reduction = flecsi_lite::reduction;
  auto& p = *s.particles;
  const std::uint64_t owned = p.owned_size();
  const auto fewest = reduce<rank_value, reduction::min>(owned).get();
  const auto most = reduce<rank_value, reduction::max>(owned).get();
  const auto fluid = reduce<fluid_count, reduction::sum>(fields<D>::kind(p)).get();
  auto line = flecsi_lite::log::info();
  line << s.program << ": " << p.global_size() << " particles (" << fluid << " fluid, " << p.global_size() - fluid
       << " walls), " << fewest << " to " << most << " per rank; kernel " << physics::kernel_name(s.physics.kernel)
       << ", eos ";
  if (!s.equation_of_state.empty())
    line << s.equation_of_state;
  else
    line << physics::eos_name(s.physics.eos.type);
  if (s.equation_of_state.empty() && s.physics.eos.type == physics::eos_type::ideal_gas)
    line << " (gamma " << s.physics.eos.ideal.gamma << ")";
}

/// Neighbours per particle over all ranks (the progress line's mean, at any step).
template<int D>
double mean_neighbours(const app_state<D>& s) {
  return mean_list_length(s);
}

/// The values of the app's own statistics columns (none unless it set extra_statistics).
template<int D>
std::vector<double> extra_statistics_values(app_state<D>& s) {
  return s.extra_statistics ? s.extra_statistics() : std::vector<double>();
}

/// The first row of a new run; a restart writes none for its restart step (the run it continues did).
template<int D>
void open_statistics(app_state<D>& s) {
  s.statistics_dt = s.dt;
  if (s.statistics_keys.file.empty()) return;
  const std::vector<std::string> description = {
    s.program + " statistics: a row every " + std::to_string(s.statistics_keys.every) +
      " steps and at the last one, written by rank 0 and flushed row by row",
    s.program + " " + flecsi_lite::app::version() + " (git " + flecsi_lite::app::git_describe() + "), " +
      std::to_string(flecsi_lite::runtime::size()) + " MPI ranks; " +
      (s.physics.gravity.enabled ? "self-gravity: total = kinetic + internal + potential + walls"
                                 : "no gravity, so no potential energy column"),
    "parameters:"};
  std::string header;
  {
    std::vector<std::string> lines = description;
    std::istringstream parameters(s.parameters_text);
    for (std::string line; std::getline(parameters, line);) lines.push_back("  " + line);
    header = statistics_header<D>(lines, s.physics.gravity.enabled, s.extra_statistics_columns);
  }
  s.statistics.open(s.statistics_keys.file, header, s.restarted ? std::optional<long>(s.step) : std::nullopt);
  if (!s.restarted)
    s.statistics.write(statistics_line<D>(s.step, s.time, 0.0, measure_conserved(s), mean_neighbours(s),
                                          s.physics.gravity.enabled, extra_statistics_values(s)));
}

/// A row every statistics_every steps and at the last; the totals of the conserved line when it
/// measured them at this step.
template<int D>
void statistics_row(app_state<D>& s) {
  const double dt = std::exchange(s.statistics_dt, s.dt);
  if (!s.statistics.is_open() || !(s.finished || s.step % s.statistics_keys.every == 0)) return;
  const conserved_totals<D> totals = s.totals_step == s.step ? s.totals : measure_conserved(s);
  s.statistics.write(statistics_line<D>(s.step, s.time, dt, totals, mean_neighbours(s), s.physics.gravity.enabled,
                                        extra_statistics_values(s)));
}

/// After the clock: a run that max_steps stopped before end_time, or whose wall_time_limit or
/// stop_file says so (one verdict for every rank), finishes at this step with a stop reason.
template<int D>
void check_run_limits(app_state<D>& s) {
  if (s.finished) {
    if (s.time < s.run.end_time && s.stop_reason.empty())
      s.stop_reason = "max_steps = " + std::to_string(s.run.max_steps) + " reached";
    return;
  }
  s.stop_reason = s.stop.check();
  s.finished = !s.stop_reason.empty();
}

/// Every checkpoint_every steps, and when the run stops before end_time (then with the command
/// that resumes it).
template<int D>
void checkpoint(app_state<D>& s) {
  const long every = s.files.checkpoint_every;
  const bool early = s.finished && !s.stop_reason.empty();
  if (!early && (every <= 0 || s.finished || s.step % every != 0)) return;
  const std::string& path = s.files.checkpoint_file;
  auto line = flecsi_lite::log::info();
  if (early)
    line << s.program << ": stopped at step " << s.step << ", t = " << s.time << " < end_time = " << s.run.end_time
         << ": " << s.stop_reason << "; ";
  if (path.empty()) {
    line << "no checkpoint (checkpoint_file = none): this run cannot be resumed";
    return;
  }
  write_restart_checkpoint(s, path,
                           {{"program", s.program},
                            {"parameters", s.parameters_text},
                            {"next_output", s.next_output},
                            {"output_due", std::int64_t{s.output_due}}});
  line << "checkpoint of step " << s.step << " (t = " << s.time << ") in '" << path << "'";
  if (!early) return;
  line << "; resume with\n  " << s.resume_command << " --set restart_file=" << path;
  // max_steps counts from step 0: the same value would stop the resumed run at once.
  if (s.run.max_steps > 0 && s.step >= s.run.max_steps)
    line << " --set max_steps=0\n(max_steps counts steps from t = 0: 0 runs to end_time, a larger value stops there)";
}
}  // namespace detail

/// The standard SPH control model (driver.hh) with the self-gravity action (place_gravity, a
/// no-op unless gravity = on), the app's problem, the initial data, the output and the
/// checkpoints; the app adds its reports on "finalize".
template<class State>
flecsi_lite::control::control_model<State> make_app_control_model(app_problem<State> problem) {
  constexpr int D = State::dimension;
  using base = app_state<D>;
  auto m = make_control_model<State>();
  place_gravity(m);
  m.action("initial_data", "particles", [problem](State& s) {
    problem.set_domain(s);
    check_gravity_domain<D>(s.physics, s.tree_settings.periodic);
    if (!s.files.restart_file.empty())
      detail::restart<D>(s);
    else if (!s.files.initial_data.empty())
      detail::read_initial_particles<D>(s);
    else
      problem.create_particles(s);
  });
  m.action("initialize", "describe_particles", [](State& s) { detail::describe_particles<D>(s); })
    .after("force_evaluation");
  m.action("initialize", "open_output", [](State& s) { detail::open_output<D>(static_cast<base&>(s)); });
  m.action("initialize", "open_statistics", [](State& s) { detail::open_statistics<D>(s); }).after("diagnostics");
  m.action("analyze", "statistics", [](State& s) { detail::statistics_row<D>(s); }).after("conserved_quantities");
  m.action("analyze", "run_limits", [](State& s) { detail::check_run_limits<D>(s); }).before("conserved_quantities");
  auto output = m.action("output", "h5part", [](State& s) {
    if (s.writer || s.snapshots) detail::write_output_step<D>(s);
  });
  auto checkpoint = m.action("output", "checkpoint", [](State& s) { detail::checkpoint<D>(s); });
  m.depends(checkpoint, output);
  m.action("finalize", "close_output", [](State& s) {
    if (s.snapshots)
      flecsi_lite::log::info() << s.program << ": " << s.snapshots->written() << " snapshots indexed in "
                               << s.snapshots->index_path();
    if (!s.writer) return;
    s.writer->finish();  // renamed by commit_outputs(), after the app's checks
    flecsi_lite::log::info() << s.program << ": wrote " << s.writer->steps_written() << " steps to "
                             << s.files.output_file;
  });
  return m;
}

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

// Compiled in the library (instances_*.cc).
FLECSPH_SPH_APP_INSTANCES(extern, 1)
FLECSPH_SPH_APP_INSTANCES(extern, 2)
FLECSPH_SPH_APP_INSTANCES(extern, 3)

}  // namespace flecsph::sph
