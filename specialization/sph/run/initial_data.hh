// Where an SPH run's particles come from when the app's problem does not create them (app.hh):
// initial data (an H5Part step or SWIFT-format initial conditions) or a checkpoint, whose
// parameters must be this run's but for the keys a restart may change (configure.hh).
#pragma once

#include "specialization/sph/files/particle_input.hh"
#include "specialization/sph/files/swift_initial_data.hh"
#include "specialization/sph/run/app_state.hh"
#include "specialization/sph/run/configure.hh"
#include "specialization/sph/run/restart.hh"
#include "specialization/sph/run/restart_checks.hh"

#include "flecsi_lite/app.hh"
#include "flecsi_lite/io.hh"
#include "flecsi_lite/runtime.hh"

#include <cstdint>
#include <cstdlib>
#include <string>

namespace flecsph::sph {
namespace detail {
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
}  // namespace detail
}  // namespace flecsph::sph
