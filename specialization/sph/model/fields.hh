// The fields of the SPH specialization on the ntree<D> topology (seed sec. 1.3): what each
// particle carries besides the topology's built-in position, id, mass and smoothing length h.
#pragma once

#include "flecsi_lite/data.hh"
#include "flecsi_lite/topology/ntree.hh"

#include <array>
#include <cstdint>
#include <string>

namespace flecsph::sph {

/// A vector in D dimensions (velocity, acceleration); positions are ntree's point<D>, the same type.
template<int D>
using vector = std::array<double, D>;

template<int D>
using particle_tree = flecsi_lite::topology::ntree::ntree<D>;

/// Persistence of fields in files: persist::output().restart().initial_required(rule), ...
namespace persist = flecsi_lite::persist;

/// FLUID particles follow the equations of motion. WALL particles are fixed boundary particles
/// (Sod's reflecting ends): they enter every sum as neighbours, their density and pressure are
/// computed like the fluid's at their fixed h, but they are never moved or heated. The forces the
/// fluid exerts on them are accumulated (boundary_impulse, boundary_work) so that the totals of
/// fluid plus walls are conserved and can be checked.
enum class particle_kind : std::int32_t { fluid = 0, wall = 1 };
}  // namespace flecsph::sph

// The storage of the kind field, compiled once in field_instances.cc.
extern template class flecsi_lite::data::field_storage<flecsph::sph::particle_kind>;
extern template flecsi_lite::data::registered_field
  flecsi_lite::data::make_registered_field<flecsph::sph::particle_kind>(std::string, flecsi_lite::data::persistence);

namespace flecsph::sph {

/// The fields of dimension D, declared once (fields are per topology type, ntree<D>), each with
/// its persistence (flecsi_lite/data/persistence.hh): what the output, the checkpoints, the
/// snapshots and the initial-data readers hold is exactly what these definitions say, with the
/// field's units and SWIFT names (`units`, `in_snapshots`, `in_swift_initial_conditions`,
/// `moving_particles_only`: walls have no such snapshot dataset; files/snapshot_layout.hh), and
/// a field that exists in files only with a feature of the run says so (`only_with`: "gravity",
/// "individual_time_steps", "viscosity_switch", "balsara_switch", "velocity_gradients",
/// "pressure_energy", "walls"; such a
/// field also takes memory only in the runs that have its feature; has_feature() in
/// files/particle_output.hh says which a run has).
///
/// Registration. Each definition registers its field with ntree<D> (data/field_registry.hh; its
/// index there is its id) when the static member is initialized. A static member of a class
/// template exists only where a program uses it (implicit instantiation) and is initialized
/// before main() in no specified order across translation units: so the registry of a program
/// holds the fields it uses, first use first. A new field needs nothing else to reach memory,
/// ghost copies, redistribution and the files its roles name; the registry's order decides only
/// the order in which a file's datasets are created (readers find them by name). Output and checkpoints hold
/// x y z, vx vy vz (zeros beyond D), m rho P u h id, kind (int32), cs, du_dt; checkpoints also
/// what the next step reads besides (accelerations and du/dt of the last force evaluation, grad-h
/// and pressure terms, the Balsara inputs with that switch, the walls' accumulators with walls), so that a restart continues
/// bitwise, and the distribution bookkeeping. Initial data: x [y z], m, h, u required; vx vy vz,
/// rho, id, kind optional. The rest (half-step values with global steps) is recomputed in every
/// step; individual time steps add their bins and step bounds (and the half-step values).
template<int D>
struct fields {
  template<class T>
  using definition = typename particle_tree<D>::template definition<T>;

  /// The powers of length in the units of a density and a pressure: per D-dimensional volume.
  static constexpr float density_length_power = -static_cast<float>(D);
  static constexpr float pressure_length_power = 2 - static_cast<float>(D);

  // The topology's own fields (x y z, id, m, h), named here so that tasks read as physics.
  static const auto& position() { return particle_tree<D>::position; }
  static const auto& id() { return particle_tree<D>::id; }
  static const auto& mass() { return particle_tree<D>::mass; }
  static const auto& smoothing_length() { return particle_tree<D>::smoothing_length; }

  // Output, restart and initial data.
  static inline const definition<particle_kind> kind{
    "kind",
    persist::output().restart().initial_optional(persist::one_of({0, 1}, "0 for fluid or 1 for wall particles"))};
  /// v (predicted during a step)
  static inline const definition<vector<D>> velocity{"velocity",
                                                     persist::as("vx", "vy", "vz")
                                                       .padded()
                                                       .output()
                                                       .restart()
                                                       .initial_optional(persist::must_be_finite("velocities"))
                                                       .units(0, 1, -1)
                                                       .in_snapshots("Velocities", "Velocities of the particles")
                                                       .in_swift_initial_conditions("Velocities")
                                                       .moving_particles_only()};
  /// eq. (1.3); read as an initial guess only
  static inline const definition<double> density{
    "rho", persist::output()
             .restart()
             .initial_optional(persist::at_least(0, "densities"))
             .units(1, density_length_power, 0)
             .in_snapshots("Densities", "Densities of the particles (mass per D-dimensional volume)")
             .in_swift_initial_conditions("Density")};
  /// specific
  static inline const definition<double> internal_energy{
    "u", persist::output()
           .restart()
           .initial_required(persist::at_least(0, "internal energies"))
           .units(0, 2, -2)
           .in_snapshots("InternalEnergies", "Specific internal energies of the particles")
           .in_swift_initial_conditions("InternalEnergy")};
  // Output and restart.
  static inline const definition<double> pressure{"P", persist::output()
                                                         .restart()
                                                         .units(1, pressure_length_power, -2)
                                                         .in_snapshots("Pressures", "Pressures of the particles")};
  static inline const definition<double> sound_speed{
    "cs", persist::output().restart().units(0, 1, -1).in_snapshots("SoundSpeeds", "Sound speeds of the particles")};
  /// eq. (1.8)
  static inline const definition<double> internal_energy_rate{
    "du_dt", persist::output()
               .restart()
               .units(0, 2, -3)
               .in_snapshots("InternalEnergyRates", "Time derivatives of the specific internal energies")
               .moving_particles_only()};
  // Restart only: what the next step reads of the last force evaluation.
  /// eq. (1.9)
  static inline const definition<vector<D>> acceleration{
    "acceleration", persist::as("ax", "ay", "az")
                      .restart()
                      .units(0, 1, -2)
                      .in_snapshots("Accelerations", "Accelerations of the particles (last force evaluation)")
                      .moving_particles_only()};
  static inline const definition<double> omega{"omega", persist::restart()};  ///< grad-h factor (1 for fixed h)
  static inline const definition<double> pressure_term{"P_over_omega_rho2", persist::restart()};  ///< P / (Omega rho^2)
  // Pressure-energy SPH only (formulation = pressure_energy, only_with("pressure_energy")): the
  // smoothed pressure P_bar = (gamma-1) sum_b m_b u_b W_ab(h_a) of the density pass (the field P
  // holds it too, from the equation of state) and its grad-h term h dP_bar/dh / (D rho Omega)
  // (Hopkins 2013, sec. 2.4); restart: with individual time steps an inactive particle drifts them.
  static inline const definition<double> smoothed_pressure{"P_bar", persist::restart().only_with("pressure_energy")};
  static inline const definition<double> pressure_grad_h{"P_bar_grad_h",
                                                         persist::restart().only_with("pressure_energy")};
  // The velocity gradients (with the Balsara switch, and div v with individual time steps) and
  // the Balsara factor: only with the physics that reads them (no memory, no file otherwise).
  static inline const definition<double> velocity_divergence{"div_v",
                                                             persist::restart().only_with("velocity_gradients")};
  static inline const definition<double> velocity_curl{"curl_v", persist::restart().only_with("balsara_switch")};
  static inline const definition<double> balsara{"balsara", persist::restart().only_with("balsara_switch")};
  /// Accumulated (per unit mass) forces and heating the fluid exerted on a wall particle: only in
  /// runs with walls (32 bytes a particle otherwise).
  static inline const definition<vector<D>> boundary_impulse{
    "boundary_impulse", persist::as("impulse_x", "impulse_y", "impulse_z").restart().only_with("walls")};
  static inline const definition<double> boundary_work{"boundary_work", persist::restart().only_with("walls")};
  // Self-gravity only (gravity = on; with it off no file holds them, only_with("gravity"), and
  // no memory is taken): the potential G Phi (output and restart, for the
  // potential energy), zeta / Omega of the grad-h gravity term (Price & Monaghan 2007), and the
  // tree's acceleration G a (in memory only: the force pass adds it).
  static inline const definition<double> gravitational_potential{
    "phi", persist::output().restart().only_with("gravity").units(0, 2, -2).in_snapshots(
             "Potentials", "Gravitational potentials G Phi of the particles")};
  static inline const definition<double> zeta_over_omega{"zeta_over_omega", persist::restart().only_with("gravity")};
  static inline const definition<vector<D>> gravity_acceleration{"gravity_acceleration"};
  // The half-step values of the leapfrog: recomputed in every step with global time steps; with
  // individual ones a particle keeps them over its step (restart only, time_steps = individual).
  static inline const definition<vector<D>> velocity_half{
    "velocity_half", persist::as("vx_half", "vy_half", "vz_half").restart().only_with("individual_time_steps")};
  static inline const definition<double> internal_energy_half{"u_half",
                                                              persist::restart().only_with("individual_time_steps")};
  // Individual time steps only (time_bins.hh; in the files with time_steps = individual): the
  // particle's bin (its step is 2^bin ticks of the timeline), where its step began and ends
  // (ticks; a woken particle's end comes early), and the length its first kick took.
  static inline const definition<std::int32_t> time_bin{"time_bin",
                                                        persist::output().restart().only_with("individual_time_steps")};
  static inline const definition<std::int64_t> step_begin{"step_begin",
                                                          persist::restart().only_with("individual_time_steps")};
  static inline const definition<std::int64_t> step_end{"step_end",
                                                        persist::restart().only_with("individual_time_steps")};
  static inline const definition<std::int64_t> kicked_ticks{"kicked_ticks",
                                                            persist::restart().only_with("individual_time_steps")};
  /// In memory only: each active particle's own criterion of the last force pass, and the
  /// smallest bin among its neighbours (the limiter's input).
  static inline const definition<double> own_time_step{"own_time_step"};
  static inline const definition<std::int32_t> neighbour_bin{"neighbour_bin"};
  // Restart only: the distribution bookkeeping (redistribution.hh). Path length since the last
  // distribution, h and position then: when to distribute again, and the keys of that
  // distribution, so that a restart sums over neighbours in the writing run's order (restart.hh).
  static inline const definition<double> drift{"drift", persist::restart()};
  static inline const definition<double> distributed_h{"distributed_h", persist::restart()};
  static inline const definition<vector<D>> distributed_position{
    "distributed_position", persist::as("distributed_x", "distributed_y", "distributed_z").restart()};
  // balance = work only: the weight of a particle in the next distribution, its neighbours at the
  // last search (zero before the first: the sample sort then balances counts).
  static inline const definition<double> work{"work"};
  // The Cullen & Dehnen (2010) viscosity switch only (viscosity_switch = on; with it off no file
  // holds them, only_with("viscosity_switch")): each particle's alpha (output and restart); div v of its last
  // update (which its neighbours' limiter reads), the one before and the time of that one, so a
  // restart continues bitwise; the shear tr(S S^T) and d(div v)/dt from the accelerations (in
  // memory only: both are computed again from the state before every use).
  static inline const definition<double> viscosity_alpha{"alpha",
                                                         persist::output().restart().only_with("viscosity_switch")};
  static inline const definition<double> switch_divergence{"switch_div_v",
                                                           persist::restart().only_with("viscosity_switch")};
  static inline const definition<double> switch_previous_divergence{"switch_div_v_previous",
                                                                    persist::restart().only_with("viscosity_switch")};
  static inline const definition<double> switch_previous_time{"switch_time",
                                                              persist::restart().only_with("viscosity_switch")};
  static inline const definition<double> switch_shear{"switch_shear"};
  static inline const definition<double> switch_divergence_rate{"switch_div_v_rate"};
};

}  // namespace flecsph::sph
