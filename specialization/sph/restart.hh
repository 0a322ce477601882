// Checkpoint and restart of an SPH run: a checkpoint (flecsi_lite/io/checkpoint.hh: one H5Part
// step, written under a temporary name and renamed) holds the particles as write_particles writes
// them plus what the next step reads besides (accelerations and du/dt of the last force
// evaluation, grad-h and pressure terms, the walls' accumulators) and the run's clock and initial
// totals. A run restarted from it takes the same steps as the run that wrote it, bitwise:
//   - the next step starts from the same fields (no recomputation of the forces at a restart:
//     they were computed with the predicted velocities of the step, not the stored ones);
//   - the particles are distributed again at the step after every checkpoint, in the writing run
//     as in the restarted one, so that both sum over neighbours in the same (key, id) order.
// The file is also a valid H5Part output (ParaView opens it) and valid initial data.
#pragma once

#include "specialization/sph/particle_input.hh"
#include "specialization/sph/particle_output.hh"

#include "flecsi_lite/io.hh"

#include <string>
#include <vector>

namespace flecsph::sph {

namespace detail {
/// Calls visit(name, reference, component) for every array a restart needs besides the output's:
/// D-vectors component by component ("ax", "ay", ...), scalars with component -1.
template<int D, class Visit>
void for_each_restart_array(particle_tree<D>& p, Visit&& visit) {
  using f = fields<D>;
  static const char* const acceleration[3] = {"ax", "ay", "az"};
  static const char* const impulse[3] = {"impulse_x", "impulse_y", "impulse_z"};
  for (int k = 0; k < D; ++k) visit(acceleration[k], f::acceleration(p), k);
  for (int k = 0; k < D; ++k) visit(impulse[k], f::boundary_impulse(p), k);
  visit("boundary_work", f::boundary_work(p), -1);
  visit("omega", f::omega(p), -1);
  visit("P_over_omega_rho2", f::pressure_term(p), -1);
  visit("balsara", f::balsara(p), -1);
  visit("div_v", f::velocity_divergence(p), -1);
  visit("curl_v", f::velocity_curl(p), -1);
}

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
  auto& p = *s.particles;
  flecsi_lite::io::write_checkpoint(path, {s.time, s.step, s.dt}, state, [&](flecsi_lite::io::h5part_writer& out) {
    write_particle_arrays(out, s);
    const std::size_t n = p.owned_size();
    std::vector<double> buffer(n);
    detail::for_each_restart_array(p, [&](const char* name, const auto& reference, int component) {
      const auto view = flecsi_lite::host_view(reference);
      for (std::size_t i = 0; i < n; ++i) {
        if constexpr (std::is_same_v<std::decay_t<decltype(view(i))>, double>) buffer[i] = view(i);
        else buffer[i] = view(i)[component];
      }
      out.write(name, buffer.data(), n);
    });
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
  read_particles(s, in, 0);
  auto& p = *s.particles;
  detail::for_each_restart_array(p, [&](const char* name, const auto& reference, int component) {
    const auto values = in.read<double>(0, name);
    auto view = flecsi_lite::host_view(reference);
    for (std::size_t i = 0; i < values.size(); ++i) {
      if constexpr (std::is_same_v<std::decay_t<decltype(view(i))>, double>) view(i) = values[i];
      else view(i)[component] = values[i];
    }
  });
  using f = fields<D>;
  const auto restore = [&](const char* name, const auto& reference) {
    const auto values = in.read<double>(0, name);
    auto view = flecsi_lite::host_view(reference);
    for (std::size_t i = 0; i < values.size(); ++i) view(i) = values[i];
  };
  restore("P", f::pressure(p));
  restore("cs", f::sound_speed(p));
  restore("du_dt", f::internal_energy_rate(p));
  s.time = contents.info.time;
  s.step = contents.info.step;
  s.dt = contents.info.dt;
  s.initial_totals = detail::load_totals<D>(contents.state, path);
  s.restarted = true;
  s.redistribute_next = true;  // as the writing run does after its checkpoint
  return contents.state;
}

} // namespace flecsph::sph
