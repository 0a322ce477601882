// Writes the SPH particles as one H5Part step (the layout ParaView's H5PartReader and the plot
// scripts read): every field whose definition (sph/fields.hh, the tree's own) has role output.
#pragma once

#include "specialization/sph/simulation.hh"

#include "flecsi_lite/data.hh"
#include "flecsi_lite/io.hh"

#include <vector>

namespace flecsph::sph {

/// The registered fields that the files of run `s` hold (as their roles say): all but the
/// self-gravity fields when gravity is off and the individual time steps' fields with global
/// steps, so that such a run writes and reads what it did before they existed.
template<int D>
std::vector<flecsi_lite::data::registered_field> files_fields(const simulation<D>& s) {
  // A field's index in the registry is its id: the gravity fields stay, without roles.
  auto all = flecsi_lite::data::registered_fields<particle_tree<D>>();
  using f = fields<D>;
  const bool gravity = s.physics.gravity.enabled, individual = s.physics.individual_time_steps();
  for (auto& field : all) {
    const bool gravity_field =
      field.name == f::gravitational_potential.name() || field.name == f::zeta_over_omega.name();
    const bool individual_field = field.name == f::velocity_half.name() ||
                                  field.name == f::internal_energy_half.name() || field.name == f::time_bin.name() ||
                                  field.name == f::step_begin.name() || field.name == f::step_end.name() ||
                                  field.name == f::kicked_ticks.name();
    const bool switch_field = field.name == f::viscosity_alpha.name() || field.name == f::switch_divergence.name() ||
                              field.name == f::switch_previous_divergence.name() ||
                              field.name == f::switch_previous_time.name();
    if ((gravity_field && !gravity) || (individual_field && !individual) ||
        (switch_field && !s.physics.viscosity_switch.enabled))
      field.persistence = flecsi_lite::data::persistence();
  }
  return all;
}

/// Collective: writes every owned particle's output fields into the open step of `out` (today
/// x y z, vx vy vz (zero beyond D), m rho P u h id, kind (0 fluid, 1 wall), cs, du_dt, and phi
/// with gravity). After distribute() the ranks' owned particles concatenated are in (key, id)
/// order, so the file's particle order does not depend on the rank count.
template<int D>
void write_particle_arrays(flecsi_lite::io::h5part_writer& out, simulation<D>& s) {
  flecsi_lite::data::write_registered_fields(*s.particles, files_fields(s), out, flecsi_lite::data::role::output);
}

/// Collective: one step at s.time (TimeValue, time, step, dt) with every owned particle.
template<int D>
void write_particles(flecsi_lite::io::h5part_writer& out, simulation<D>& s) {
  out.begin_step({s.time, s.step, s.dt});
  write_particle_arrays(out, s);
  out.end_step();
}

}  // namespace flecsph::sph
