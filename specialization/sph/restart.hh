// Checkpoint and restart of an SPH run: a checkpoint (flecsi_lite/io/checkpoint.hh: one H5Part
// step, written under a temporary name and renamed) holds every field whose definition has role
// output or restart (sph/fields.hh: the output's arrays plus what the next step reads besides)
// and the run's clock and initial totals; a restart reads back every field with role restart.
// A run restarted from it takes the same steps as the run that wrote it, bitwise:
//   - the next step starts from the same fields (no recomputation of the forces at a restart:
//     they were computed with the predicted velocities of the step, not the stored ones);
//   - the particles are distributed again at the step after every checkpoint, in the writing run
//     as in the restarted one, so that both sum over neighbours in the same (key, id) order.
// The file is also a valid H5Part output (ParaView opens it) and valid initial data.
#pragma once

#include "specialization/sph/particle_input.hh"
#include "specialization/sph/particle_output.hh"

#include "flecsi_lite/data.hh"
#include "flecsi_lite/io.hh"

#include <cstdint>
#include <string>

namespace flecsph::sph {

namespace detail {
/// The initial totals as run-state entries "initial_<quantity>", and back.
template<int D>
void store_totals(const conserved_totals<D>& t, flecsi_lite::io::run_state& state) {
  state["initial_mass"] = t.mass;
  state["initial_kinetic"] = t.kinetic;
  state["initial_internal"] = t.internal;
  state["initial_total"] = t.total;
  state["initial_boundary"] = t.boundary;
  for (int k = 0; k < D; ++k) state["initial_momentum_" + std::to_string(k)] = t.momentum[k];
  for (int k = 0; k < angular_components<D>; ++k)
    state["initial_angular_momentum_" + std::to_string(k)] = t.angular_momentum[k];
}

template<int D>
conserved_totals<D> load_totals(const flecsi_lite::io::run_state& state, const std::string& path) {
  const auto get = [&](const std::string& name) {
    const auto found = state.find(name);
    if (found == state.end())
      throw flecsi_lite::io::missing_attribute_error("checkpoint '" + path + "' lacks the run state '" + name + "'");
    return flecsi_lite::io::attribute_as<double>(found->second, "run state '" + name + "' of '" + path + "'");
  };
  conserved_totals<D> t;
  t.mass = get("initial_mass");
  t.kinetic = get("initial_kinetic");
  t.internal = get("initial_internal");
  t.total = get("initial_total");
  t.boundary = get("initial_boundary");
  for (int k = 0; k < D; ++k) t.momentum[k] = get("initial_momentum_" + std::to_string(k));
  for (int k = 0; k < angular_components<D>; ++k)
    t.angular_momentum[k] = get("initial_angular_momentum_" + std::to_string(k));
  return t;
}
} // namespace detail

/// Collective: writes the checkpoint `path` of `s` now, with `state` (the app's entries) and the
/// dimension and initial totals; the next step distributes the particles again.
template<int D>
void write_restart_checkpoint(simulation<D>& s, const std::string& path, flecsi_lite::io::run_state state) {
  state["dimension"] = std::int64_t{D};
  detail::store_totals(s.initial_totals, state);
  flecsi_lite::io::write_checkpoint(path, {s.time, s.step, s.dt}, state, [&](flecsi_lite::io::h5part_writer& out) {
    using flecsi_lite::data::role;
    flecsi_lite::data::write_fields(*s.particles, out, role::output | role::restart);
  });
  s.redistribute_next = true;
}

/// Collective: restores `s` (particles, clock, initial totals) from the checkpoint `path` and
/// marks it restarted, so that the driver does not recompute the state of the restart step.
/// The checkpoint's run state must hold the dimension D and every entry of `required` (e.g. the
/// program) with the same value. The tree settings (box, periodic axes) must be set. Returns the
/// checkpoint's run state.
template<int D>
flecsi_lite::io::run_state read_restart_checkpoint(simulation<D>& s, const std::string& path,
                                                   flecsi_lite::io::run_state required = {}) {
  const flecsi_lite::io::h5part_reader in(path);
  const auto contents = flecsi_lite::io::read_checkpoint(in);
  required["dimension"] = std::int64_t{D};
  for (const auto& [name, value] : required) {
    const auto found = contents.state.find(name);
    const std::string written = found == contents.state.end() ? "none" : flecsi_lite::io::to_string(found->second);
    if (found == contents.state.end() || found->second != value)
      throw flecsi_lite::io::layout_error("checkpoint '" + path + "' was written with " + name + " = " + written +
                                          ", this run has " + name + " = " + flecsi_lite::io::to_string(value));
  }
  create_particles_for(s, in, 0);
  flecsi_lite::data::read_fields(*s.particles, in, 0, flecsi_lite::data::role::restart);
  s.time = contents.info.time;
  s.step = contents.info.step;
  s.dt = contents.info.dt;
  s.initial_totals = detail::load_totals<D>(contents.state, path);
  s.restarted = true;
  s.redistribute_next = true;  // as the writing run does after its checkpoint
  return contents.state;
}

} // namespace flecsph::sph
