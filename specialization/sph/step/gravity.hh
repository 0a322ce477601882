// Self-gravity in the SPH step (Price & Monaghan 2007, MNRAS 374, 1347): the kernel-softened pair
// of physics/gravity_softening.hh, symmetrised in h, as the near field of the framework's
// distributed gravity tree (ntree::gravity_tree: Barnes-Hut multipoles, optional GADGET-2
// relative criterion) over the owned particles; the action that places it in the step by name.
//
//   place_gravity(m);   // "gravity" after density, before forces, in initialize and advance
//
// The action stores G a (field gravity_acceleration), which the force pass adds to the SPH
// acceleration together with the grad-h gravity term (forces.hh), and G Phi (field phi, output),
// whose W = 1/2 sum m Phi enters the conserved totals (conserved.hh). Wall particles take part as
// sources and targets like fluid ones (the kick adds their acceleration to their boundary
// impulse, so momentum stays conserved with walls too). With gravity off it does nothing.
#pragma once

#include "specialization/sph/model/simulation.hh"

#include "specialization/physics/gravity_softening.hh"
#include "specialization/physics/kernels.hh"

#include "flecsi_lite/control.hh"
#include "flecsi_lite/execution.hh"
#include "flecsi_lite/runtime.hh"
#include "flecsi_lite/topology/ntree.hh"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <utility>
#include <vector>

namespace flecsph::sph {

/// The near field of the gravity walk: the softened pair of `Shape` symmetrised in h,
///   potential (phi(r, h_i) + phi(r, h_j)) / 2,   radial (g(r, h_i) + g(r, h_j)) / (2 r),
/// the same bits for (i, j) and (j, i), so pair forces are exactly opposite (momentum conserved to
/// round-off at theta = 0); Newtonian from 2 max(h_i, h_j) on; radial 0 at r = 0 (the self pair).
template<class Shape>
struct softened_pair_field {
  KOKKOS_INLINE_FUNCTION tree::softened_pair operator()(double r, double h_target, double h_source) const {
    using softening = physics::softened_gravity<Shape>;
    const double potential = 0.5 * (softening::potential(r, h_target) + softening::potential(r, h_source));
    if (r == 0) return {potential, 0.0};
    return {potential, 0.5 * (softening::radial(r, h_target) + softening::radial(r, h_source))};
  }
};

namespace detail {
/// Stores the tree's results (G = 1) scaled by G in the fields: of every particle, or of those
/// `stored` marks (when given).
template<int D>
void store_gravity(double G, const std::vector<vector<D>>& acceleration, const std::vector<double>& potential,
                   const std::vector<std::uint8_t>& stored, rw<vector<D>> gravity_acceleration,
                   rw<double> gravitational_potential) {
  flecsi_lite::forall(
    gravity_acceleration.size(),
    [&](std::size_t a) {
      if (!stored.empty() && !stored[a]) return;
      for (int k = 0; k < D; ++k) gravity_acceleration(a)[k] = G * acceleration[a][k];
      gravitational_potential(a) = G * potential[a];
    },
    "sph::store_gravity");
}

/// The walk of the groups holding a particle `wanted` marks (empty: all), stored for those
/// particles; returns the interactions evaluated.
template<int D>
gravity_record walk_gravity(simulation<D>& s, const tree::gravity_tree<D>& gravity, std::vector<std::uint8_t> wanted) {
  using f = fields<D>;
  auto& p = *s.particles;
  const std::size_t n = p.owned_size();
  std::vector<vector<D>> acceleration(n);
  std::vector<double> potential(n);
  const tree::gravity_counts counts = physics::dispatch_kernel<D>(s.physics.kernel, [&](auto kernel) {
    using shape = typename decltype(kernel)::shape;
    return gravity.evaluate(softened_pair_field<shape>{}, acceleration.data(), potential.data(),
                            wanted.empty() ? nullptr : wanted.data());
  });
  flecsi_lite::execute<store_gravity<D>>(s.physics.gravity.constant, std::move(acceleration), std::move(potential),
                                         std::move(wanted), f::gravity_acceleration(p), f::gravitational_potential(p));
  return {counts.node_interactions, counts.particle_interactions, gravity.imported_nodes(),
          gravity.imported_particles()};
}

/// With individual time steps, which owned particles are active (their step ends at the clock's
/// next tick; walls always); empty when every particle is.
template<int D>
std::vector<std::uint8_t> active_particles(simulation<D>& s) {
  if (!s.physics.individual_time_steps() || s.initializing) return {};
  const auto step_end = flecsi_lite::host_read(fields<D>::step_end(*s.particles));
  std::vector<std::uint8_t> active(s.particles->owned_size());
  for (std::size_t a = 0; a < active.size(); ++a) active[a] = step_end(a) == s.clock.next;
  return active;
}
}  // namespace detail

/// Collective: the tree gravity of the owned particles at their current positions, h (final:
/// call after the density) and masses, into the fields gravity_acceleration (G a) and phi (G Phi).
/// The relative criterion compares with the previous step's total |a| (field acceleration, zero
/// at the start: theta alone decides then). The ranks' owned particles are in the (key, id) order
/// of the last distribution (the ntree's key field), so the tree, hence every sum, is the same on
/// any number of ranks.
///
/// With individual time steps the forces read the active particles' values only: the walk covers
/// the target groups holding an active particle, and the other groups' walk is deferred
/// (s.deferred_fields, on the same tree) until the potential energy or the files read every
/// particle's phi. Each particle's values are those of the whole walk, to the bit, whenever they
/// are read (the inactive ones' from their last active step made the Evrard collapse's energy
/// seem off by 2.1e-2 in mid-collapse, against 1.9e-3). When the deferred walks of the two steps
/// before were both needed (totals in every step), the step walks every group at once: the same
/// bits, without walking twice the groups that hold both kinds.
/// last_gravity counts the interactions evaluated in the step. Does nothing with gravity off.
template<int D>
gravity_record update_gravity(simulation<D>& s) {
  gravity_record record;
  s.deferred_fields = nullptr;  // made for positions the drift has since moved
  if (!s.physics.gravity.enabled) return record;
  if constexpr (D == 3) {
    using f = fields<D>;
    auto& p = *s.particles;
    const auto& settings = s.physics.gravity;
    flecsi_lite::timers::scoped timer("sph::gravity");
    const std::size_t n = p.owned_size();
    // The fields as the last launches left them (host_read waits for them).
    const auto keys = flecsi_lite::host_read(particle_tree<D>::key(p));
    const auto x = flecsi_lite::host_read(f::position()(p));
    const auto m = flecsi_lite::host_read(f::mass()(p));
    const auto h = flecsi_lite::host_read(f::smoothing_length()(p));
    tree::gravity_options options;
    options.theta = settings.theta;
    options.relative_criterion = settings.criterion == gravity_criterion::relative;
    options.relative_tolerance = settings.relative_tolerance;
    std::vector<double> previous;  // |a_old| / G: the tree's units (G = 1)
    if (options.relative_criterion) {
      const auto a_old = flecsi_lite::host_read(f::acceleration(p));
      previous.resize(n);
      for (std::size_t a = 0; a < n; ++a) {
        double a2 = 0;
        for (int k = 0; k < D; ++k) a2 += a_old(a)[k] * a_old(a)[k];
        previous[a] = std::sqrt(a2) / settings.constant;
      }
    }
    auto gravity = std::make_shared<tree::gravity_tree<D>>();
    gravity->build(keys.data(), x.data(), m.data(), h.data(), previous.empty() ? nullptr : previous.data(), n, options,
                   flecsi_lite::runtime::communicator());
    std::vector<std::uint8_t> active = detail::active_particles(s);
    if (active.empty()) return detail::walk_gravity(s, *gravity, {});
    // Where the totals are read every step (the default statistics rows), deferring only costs
    // the groups that hold both kinds twice: after two such steps every group is walked at once,
    // and an empty deferred work keeps noting whether the next step's is read.
    s.deferred_reads_in_a_row = std::exchange(s.deferred_fields_read, false) ? s.deferred_reads_in_a_row + 1 : 0;
    if (s.deferred_reads_in_a_row >= 2) {
      s.deferred_fields = [] {};
      return detail::walk_gravity(s, *gravity, {});
    }
    std::vector<std::uint8_t> inactive(active.size());
    for (std::size_t a = 0; a < active.size(); ++a) inactive[a] = !active[a];
    record = detail::walk_gravity(s, *gravity, std::move(active));
    s.deferred_fields = [&s, gravity, inactive = std::move(inactive)] {
      flecsi_lite::timers::scoped deferred_timer("sph::gravity");
      const gravity_record rest = detail::walk_gravity(s, *gravity, inactive);
      s.last_gravity.node_interactions += rest.node_interactions;
      s.last_gravity.particle_interactions += rest.particle_interactions;
    };
  }
  return record;
}

/// Places the action "gravity" in the force evaluation right after "density" (h and rho final), so
/// before "equation_of_state" and "forces" (which adds its acceleration): at t = 0 (not after a
/// restart, whose checkpoint holds the step's forces and potential) and in every step. With
/// gravity off the action returns at once.
template<class State>
void place_gravity(flecsi_lite::control::control_model<State>& m) {
  m.action("force_evaluation", "gravity", [](State& s) { s.last_gravity = update_gravity(s); }).after("density");
}

}  // namespace flecsph::sph
