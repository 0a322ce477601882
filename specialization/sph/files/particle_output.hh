// Writes the SPH particles as one H5Part step (the layout ParaView's H5PartReader and the plot
// scripts read): every field whose definition (sph/fields.hh, the tree's own) has role output.
#pragma once

#include "specialization/sph/model/simulation.hh"

#include "flecsi_lite/data.hh"
#include "flecsi_lite/io.hh"

#include <stdexcept>
#include <string>
#include <vector>

namespace flecsph::sph {

/// Whether run `s` has `feature`, a name a field's definition may give (persist only_with): the
/// SPH features are "gravity" (gravity = on), "individual_time_steps" (time_steps = individual),
/// "viscosity_switch" (viscosity_switch = on), "balsara_switch" (balsara_switch = on),
/// "velocity_gradients" (div v is kept: the Balsara switch or individual time steps),
/// "pressure_energy" (formulation = pressure_energy) and "walls" (some particle is a wall).
template<int D>
bool has_feature(const simulation<D>& s, const std::string& feature) {
  if (feature == "gravity") return s.physics.gravity.enabled;
  if (feature == "individual_time_steps") return s.physics.individual_time_steps();
  if (feature == "viscosity_switch") return s.physics.viscosity_switch.enabled;
  if (feature == "balsara_switch") return s.physics.balsara;
  if (feature == "velocity_gradients") return s.physics.velocity_gradients();
  if (feature == "pressure_energy") return s.physics.pressure_energy();
  if (feature == "walls") return s.has_walls;
  throw std::logic_error("sph: a field is declared only_with(\"" + feature +
                         "\"), which is no feature of an SPH run (gravity, individual_time_steps, "
                         "viscosity_switch, balsara_switch, velocity_gradients, pressure_energy, walls)");
}

/// The registered fields that the files of run `s` hold (as their roles say): a field declared
/// only with a feature the run lacks (fields.hh) keeps no role, so that such a run writes and
/// reads what it did before that field existed.
template<int D>
std::vector<flecsi_lite::data::registered_field> files_fields(const simulation<D>& s) {
  // A field's index in the registry is its id: every field stays, some without roles.
  auto all = flecsi_lite::data::registered_fields<particle_tree<D>>();
  for (auto& field : all)
    if (!field.persistence.feature().empty() && !has_feature(s, field.persistence.feature()))
      field.persistence = flecsi_lite::data::persistence();
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
