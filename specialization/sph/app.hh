// The frame every SPH app (sod, sedov, ...) shares, so that an app is its problem and its
// reports: the settings read from the parameters, initial particles from the problem, from an
// H5Part file or from a checkpoint, the H5Part output at a cadence, checkpoints, and main() with
// its options and error handling.
//
//   struct my_run : sph::app_state<D> { my::problem problem; };
//   auto m = sph::make_app_control_model<my_run>({set_domain, create_particles});
//   m.action("finalize", "report", report);          // the app's own comparisons
//   return m.execute(state);
#pragma once

#include "specialization/sph/driver.hh"
#include "specialization/sph/particle_input.hh"
#include "specialization/sph/particle_output.hh"
#include "specialization/sph/restart.hh"

#include "flecsi_lite/control.hh"
#include "flecsi_lite/io.hh"
#include "flecsi_lite/runtime.hh"

#include <functional>
#include <memory>
#include <string>

namespace flecsph::sph {

/// A run of an app: the simulation plus its files.
template<int D>
struct app_state : simulation<D> {
  std::string program;          ///< the app's name, in messages and files
  std::string parameters_text;  ///< the resolved parameters, stored in every file
  io_settings files;
  double next_output = 0;  ///< simulation time of the next output
  std::unique_ptr<flecsi_lite::io::h5part_writer> writer;
  /// Root attributes of the output that describe the problem (gamma, initial states, ...).
  flecsi_lite::io::run_state description;
};

/// Reads the physics, run-control and file keys into `s`.
template<int D>
void configure(app_state<D>& s, const std::string& program, const flecsi_lite::runtime::parameters& p) {
  s.program = program;
  s.physics = physics_from(p);
  s.run = run_settings_from(p);
  s.files = io_settings_from(p);
  s.parameters_text = p.resolved_text();
}

/// What an app adds to the standard model: the domain (box and periodic axes of
/// s.tree_settings) and, unless the particles come from a file, the particles themselves.
template<class State>
struct app_problem {
  std::function<void(State&)> set_domain;
  std::function<void(State&)> create_particles;
};

namespace detail {
template<int D>
void write_output_step(app_state<D>& s) {
  write_particles(*s.writer, s);
  s.next_output = s.files.output_every > 0 ? s.time + s.files.output_every : s.run.end_time;
}

template<int D>
void open_output(app_state<D>& s) {
  if (s.files.output_file.empty()) return;
  s.writer = std::make_unique<flecsi_lite::io::h5part_writer>(s.files.output_file);
  s.writer->describe_run({s.program, s.parameters_text, D});
  s.writer->set_attribute("gamma", s.physics.eos.ideal.gamma);
  s.writer->set_attribute("ranks", static_cast<std::int64_t>(flecsi_lite::runtime::size()));
  for (const auto& [name, value] : s.description) s.writer->set_attribute(name, value);
  write_output_step(s);
}

template<int D>
void read_initial_particles(app_state<D>& s) {
  const flecsi_lite::io::h5part_reader in(s.files.initial_data);
  const auto step = read_particles(s, in, s.files.initial_data_step);
  flecsi_lite::log::info() << s.program << ": " << in.particle_count(step) << " initial particles from "
                           << describe_input_step(in, step);
}

template<int D>
void restart(app_state<D>& s) {
  read_restart_checkpoint(s, s.files.restart_file, {{"program", s.program}});
  flecsi_lite::log::info() << s.program << ": restarting at step " << s.step << ", t = " << s.time << " from '"
                           << s.files.restart_file << "'";
}

template<int D>
void checkpoint(app_state<D>& s) {
  const long every = s.files.checkpoint_every;
  if (every <= 0 || s.finished || s.step % every != 0) return;
  write_restart_checkpoint(s, s.files.checkpoint_file, {{"program", s.program}, {"parameters", s.parameters_text}});
  flecsi_lite::log::info() << s.program << ": checkpoint of step " << s.step << " (t = " << s.time << ") in '"
                           << s.files.checkpoint_file << "'";
}
} // namespace detail

/// The standard SPH control model (driver.hh) with the app's problem, the initial data, the
/// output and the checkpoints; the app adds its reports on "finalize".
template<class State>
flecsi_lite::control::control_model<State> make_app_control_model(app_problem<State> problem) {
  constexpr int D = State::dimension;
  using base = app_state<D>;
  auto m = make_control_model<State>();
  m.action("initial_data", "particles", [problem](State& s) {
    problem.set_domain(s);
    if (!s.files.restart_file.empty()) detail::restart<D>(s);
    else if (!s.files.initial_data.empty()) detail::read_initial_particles<D>(s);
    else problem.create_particles(s);
  });
  m.action("initialize", "open_output", [](State& s) { detail::open_output<D>(static_cast<base&>(s)); });
  auto output = m.action("output", "h5part", [](State& s) {
    if (s.writer && (s.finished || s.time >= s.next_output)) detail::write_output_step<D>(s);
  });
  auto checkpoint = m.action("output", "checkpoint", [](State& s) { detail::checkpoint<D>(s); });
  m.depends(checkpoint, output);
  m.action("finalize", "close_output", [](State& s) {
    if (!s.writer) return;
    s.writer->close();
    flecsi_lite::log::info() << s.program << ": wrote " << s.writer->steps_written() << " steps to "
                             << s.files.output_file;
  });
  return m;
}

/// An app's main(): its name and help, its parameter keys and options, and the run.
struct app_definition {
  std::string program;
  std::string summary;  ///< first line of --help
  std::function<void(flecsi_lite::runtime::parameter_schema&)> declare_parameters;
  std::function<void(flecsi_lite::runtime::options&)> declare_options;  ///< the app's checks
  std::function<int(const flecsi_lite::runtime::parameters&, const flecsi_lite::runtime::options&)> run;
};

/// Parses the options (parameter file, --set KEY=VALUE, --parameters-help and the app's), loads
/// the parameters and runs. Exit status: the run's; 2 for bad parameters; 3 for any other error
/// (bad files, impossible values), each reported on rank 0 with what was wrong.
int app_main(int argc, char** argv, const app_definition& app);

} // namespace flecsph::sph
