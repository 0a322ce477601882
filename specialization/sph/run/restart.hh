// Checkpoint and restart of an SPH run: a checkpoint (flecsi_lite/io/checkpoint.hh: one H5Part
// step, written under a temporary name and renamed) holds every field whose definition has role
// output or restart (sph/fields.hh: the output's arrays plus what the next step reads besides,
// and the distribution bookkeeping) and the run's clock and initial totals; a restart checks the
// clock and the ids, then reads back every field with role restart.
// A run restarted from it takes the same steps as the run that wrote it, bitwise, on any rank
// count, and writing a checkpoint changes nothing in the writing run:
//   - the next step starts from the same fields (no recomputation of the forces at a restart:
//     they were computed with the predicted velocities of the step, not the stored ones);
//   - the restart distributes the particles from their positions and h at the writing run's last
//     distribution (stored), so that the keys, hence the (key, id) order of every neighbour sum,
//     are the writing run's; the path lengths since then decide the next distribution as they
//     would have in the writing run.
// The file is also a valid H5Part output (ParaView opens it) and valid initial data.
#pragma once

#include "specialization/sph/files/particle_input.hh"
#include "specialization/sph/files/particle_output.hh"
#include "specialization/sph/model/neighbourhood.hh"
#include "specialization/sph/model/tasks.hh"
#include "specialization/sph/model/walls.hh"
#include "specialization/sph/run/restart_checks.hh"

#include "flecsi_lite/data.hh"
#include "flecsi_lite/io.hh"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <sstream>
#include <string>
#include <utility>

namespace flecsph::sph {

/// The run-state entry `name` of the checkpoint `path` (its root attribute "state:<name>"); a
/// missing one is an error naming both.
inline const flecsi_lite::io::attribute_value& checkpoint_entry(const flecsi_lite::io::run_state& state,
                                                                const std::string& name, const std::string& path) {
  const auto found = state.find(name);
  if (found == state.end())
    throw flecsi_lite::io::missing_attribute_error("checkpoint '" + path + "' lacks the run state '" + name +
                                                   "' (root attribute 'state:" + name + "')");
  return found->second;
}

namespace detail {
/// The initial totals as run-state entries "initial_<quantity>", and back.
template<int D>
void store_totals(const conserved_totals<D>& t, bool gravity, flecsi_lite::io::run_state& state) {
  if (gravity) state["initial_potential"] = t.potential;
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
conserved_totals<D> load_totals(const flecsi_lite::io::run_state& state, bool gravity, const std::string& path) {
  const auto get = [&](const std::string& name) {
    return flecsi_lite::io::attribute_as<double>(checkpoint_entry(state, name, path),
                                                 "run state '" + name + "' of '" + path + "'");
  };
  conserved_totals<D> t;
  t.mass = get("initial_mass");
  t.kinetic = get("initial_kinetic");
  t.internal = get("initial_internal");
  t.total = get("initial_total");
  t.boundary = get("initial_boundary");
  if (gravity) t.potential = get("initial_potential");
  for (int k = 0; k < D; ++k) t.momentum[k] = get("initial_momentum_" + std::to_string(k));
  for (int k = 0; k < angular_components<D>; ++k)
    t.angular_momentum[k] = get("initial_angular_momentum_" + std::to_string(k));
  return t;
}
/// Individual time steps: the timeline (origin, tick, now, next) as run-state entries, and back.
inline void store_timeline(const timeline& clock, flecsi_lite::io::run_state& state) {
  state["timeline_origin"] = clock.origin;
  state["timeline_tick"] = clock.tick;
  state["timeline_now"] = clock.now;
  state["timeline_next"] = clock.next;
}

/// The checkpoint's timeline into s.clock when s has individual time steps; an error naming the
/// file and key time_steps when the checkpoint was written with the other stepping, or naming
/// end_time when the run's end is not the timeline's (its ticks are fractions of the span).
template<int D>
void load_timeline(simulation<D>& s, const flecsi_lite::io::run_state& state, const std::string& path) {
  const bool written_individual = state.count("timeline_tick") > 0;
  if (written_individual != s.physics.individual_time_steps())
    throw flecsi_lite::io::layout_error(
      "checkpoint '" + path + "' was written with time_steps = " + (written_individual ? "individual" : "global") +
      ", this run has time_steps = " + (written_individual ? "global" : "individual") +
      ": a run continues with the stepping it started with");
  if (!written_individual) return;
  const auto real = [&](const std::string& name) {
    return flecsi_lite::io::attribute_as<double>(checkpoint_entry(state, name, path),
                                                 "run state '" + name + "' of '" + path + "'");
  };
  const auto integer = [&](const std::string& name) {
    return flecsi_lite::io::attribute_as<std::int64_t>(checkpoint_entry(state, name, path),
                                                       "run state '" + name + "' of '" + path + "'");
  };
  s.clock.origin = real("timeline_origin");
  s.clock.tick = real("timeline_tick");
  s.clock.now = integer("timeline_now");
  s.clock.next = integer("timeline_next");
  if (!(s.clock.now >= 0 && s.clock.now < s.clock.next && s.clock.next <= timeline::span && s.clock.tick > 0))
    throw flecsi_lite::io::layout_error("checkpoint '" + path + "': the timeline entries (now " +
                                        std::to_string(s.clock.now) + ", next " + std::to_string(s.clock.next) +
                                        ") are not a step within the span of 2^40 ticks");
  if (timeline::spanning(s.clock.origin, s.run.end_time).tick != s.clock.tick) {
    std::ostringstream m;
    m.precision(17);
    m << "checkpoint '" << path << "' holds individual time steps on a timeline ending at t = " << s.clock.end_time()
      << ", this run has end_time = " << s.run.end_time
      << ": the bins are fractions of that span, so the run continues only with end_time = " << s.clock.end_time();
    throw flecsi_lite::io::layout_error(m.str());
  }
}

/// Exchanges the current positions and h with those of the last distribution (twice: back).
template<int D>
void swap_distribution_state(rw<vector<D>> x, rw<double> h, rw<vector<D>> distributed_x, rw<double> distributed_h) {
  flecsi_lite::forall(
    x.size(),
    [&](std::size_t a) {
      std::swap(x(a), distributed_x(a));
      std::swap(h(a), distributed_h(a));
    },
    "sph::swap_distribution_state");
}

/// Collective: distributes the particles as the writing run last did (keys and ghosts from the
/// positions and h then), back to the current positions and h, and searches the neighbours.
template<int D>
void distribute_as_written(simulation<D>& s) {
  using f = fields<D>;
  auto& p = *s.particles;
  const auto swap = [&] {
    flecsi_lite::execute<swap_distribution_state<D>>(f::position()(p), f::smoothing_length()(p),
                                                     f::distributed_position(p), f::distributed_h(p));
  };
  swap();
  p.distribute();
  swap();
  ++s.distributions;
  p.refresh_local_tree();
  find_neighbours(p, s.neighbours, s.physics.list_skin, s.physics.neighbour_lists);
  ++s.searches;
}

/// The checkpoint's clock as a restart needs it: time, dt and step present and finite, dt > 0,
/// step >= 0, time before end_time. Throws layout_error naming the file and the attribute.
inline void check_clock(const flecsi_lite::io::h5part_reader& in, const flecsi_lite::io::step_info& info,
                        double end_time) {
  const auto names = in.step_attribute_names(0);
  const auto has = [&](const char* name) { return std::find(names.begin(), names.end(), name) != names.end(); };
  const std::string where = "checkpoint '" + in.path() + "' Step#0: ";
  const auto fail = [&](const std::string& what) { throw flecsi_lite::io::layout_error(where + what); };
  for (const char* name : {"dt", "step"})
    if (!has(name)) fail("no attribute '" + std::string(name) + "'");
  // 'time' itself: TimeValue is ParaView's copy, not the run's clock (README: a restart needs 'time').
  if (!has("time")) fail("no attribute 'time'");
  const auto text = [](double v) {
    std::ostringstream out;
    out.precision(17);
    out << v;
    return out.str();
  };
  if (!std::isfinite(info.time)) fail("attribute 'time' = " + text(info.time) + " is not finite");
  if (!std::isfinite(info.dt) || !(info.dt > 0)) fail("attribute 'dt' = " + text(info.dt) + " must be finite and > 0");
  if (info.step < 0) fail("attribute 'step' = " + std::to_string(info.step) + " must be >= 0");
  if (!(info.time < end_time))
    fail("attribute 'time' = " + text(info.time) + " is not before end_time = " + text(end_time) +
         ": the run it holds is complete (raise end_time to continue it)");
}

/// Ids integral and unique over all ranks. Throws layout_error naming the file and dataset 'id'.
inline void check_ids(const flecsi_lite::io::h5part_reader& in) {
  namespace io = flecsi_lite::io;
  const std::string where = "checkpoint '" + in.path() + "' Step#0 dataset 'id'";
  if (!in.has_dataset(0, "id")) throw io::layout_error(where + " is missing");
  const auto type = in.dataset_type(0, "id");
  if (type != io::element_type::uint64 && type != io::element_type::int64 && type != io::element_type::int32)
    throw io::layout_error(where + " holds " + io::element_type_name(type) + " values: ids must be integers");
  const auto ids = in.read<std::uint64_t>(0, "id", in.block(0));
  if (const auto twice = io::duplicate_id(ids.data(), ids.size(), in.communicator()))
    throw io::layout_error(where + ": id " + std::to_string(*twice) + " belongs to more than one particle");
}
}  // namespace detail

/// Collective: writes the checkpoint `path` of `s` now, with `state` (the app's entries) and the
/// dimension and initial totals. The run goes on as it would without it.
template<int D>
void write_restart_checkpoint(simulation<D>& s, const std::string& path, flecsi_lite::io::run_state state) {
  state["dimension"] = std::int64_t{D};
  detail::store_totals(s.initial_totals, s.physics.gravity.enabled, state);
  if (s.physics.individual_time_steps()) detail::store_timeline(s.clock, state);
  flecsi_lite::io::write_checkpoint(path, {s.time, s.step, s.dt}, state, [&](flecsi_lite::io::h5part_writer& out) {
    using flecsi_lite::data::role;
    flecsi_lite::data::write_registered_fields(*s.particles, files_fields(s), out, role::output | role::restart);
  });
}

/// Collective: restores `s` (particles, clock, initial totals) from the checkpoint `path`,
/// distributes them as the writing run had (detail::distribute_as_written) and marks it
/// restarted, so that the driver does not recompute the state of the restart step. The
/// checkpoint's clock must be usable (detail::check_clock, with s.run.end_time), its ids unique,
/// with individual time steps its timeline, clock and step windows consistent (restart_checks.hh),
/// its run state must hold the dimension D and every entry of `required` (e.g. the program)
/// with the same value, and the clock and run state must match their checksums
/// (flecsi_lite::io::verify_run_state). The tree settings (box, periodic axes) must be set. Returns the
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
  detail::check_clock(in, contents.info, s.run.end_time);
  detail::check_ids(in);
  create_particles_for(s, in, 0);
  // The walls' accumulators are in the checkpoints of runs with walls only.
  s.has_walls = in.has_dataset(0, fields<D>::boundary_work.name());
  flecsi_lite::data::read_registered_fields(*s.particles, files_fields(s), in, 0, flecsi_lite::data::role::restart);
  if (!s.has_walls && count_walls(s) > 0)
    throw flecsi_lite::io::layout_error("checkpoint '" + path +
                                        "' holds wall particles (kind = 1) but no dataset boundary_work: their "
                                        "accumulated impulse and work are missing");
  s.time = contents.info.time;
  s.step = contents.info.step;
  s.dt = contents.info.dt;
  s.initial_totals = detail::load_totals<D>(contents.state, s.physics.gravity.enabled, path);
  detail::load_timeline(s, contents.state, path);
  if (s.physics.individual_time_steps()) {
    detail::check_clock_on_timeline(path, s.clock, s.time, s.dt, s.run.end_time);
    detail::check_time_bins(in, s.clock);
  }
  // Last, so that the checks above name what is inconsistent when they can; the checksums then
  // refuse any other changed clock or run-state value (one that would continue another run).
  flecsi_lite::io::verify_run_state(in, contents);
  detail::distribute_as_written(s);
  s.restarted = true;
  return contents.state;
}

}  // namespace flecsph::sph
