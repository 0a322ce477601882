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
/// Stores the tree's results (G = 1) scaled by G in the fields.
template<int D>
void store_gravity(double G, const std::vector<vector<D>>& acceleration, const std::vector<double>& potential,
                   wo<vector<D>> gravity_acceleration, wo<double> gravitational_potential) {
  flecsi_lite::forall(
    gravity_acceleration.size(),
    [&](std::size_t a) {
      for (int k = 0; k < D; ++k) gravity_acceleration(a)[k] = G * acceleration[a][k];
      gravitational_potential(a) = G * potential[a];
    },
    "sph::store_gravity");
}
}  // namespace detail

/// Collective: the tree gravity of the owned particles at their current positions, h (final:
/// call after the density) and masses, into the fields gravity_acceleration (G a) and phi (G Phi).
/// The relative criterion compares with the previous step's total |a| (field acceleration, zero
/// at the start: theta alone decides then). The ranks' owned particles are in the (key, id) order
/// of the last distribution (the ntree's key field), so the tree, hence every sum, is the same on
/// any number of ranks. With individual time steps too every particle is evaluated in every
/// system step: the forces use the active particles' values only, but the potential energy needs
/// every particle's potential at the same time (with the inactive ones' from their last active
/// step the Evrard collapse's energy seemed off by 2.1e-2 in mid-collapse, against 1.9e-3).
/// Does nothing with gravity off.
template<int D>
gravity_record update_gravity(simulation<D>& s) {
  gravity_record record;
  if (!s.physics.gravity.enabled) return record;
  if constexpr (D == 3) {
    using f = fields<D>;
    auto& p = *s.particles;
    const auto& settings = s.physics.gravity;
    flecsi_lite::timers::scoped timer("sph::gravity");
    const std::size_t n = p.owned_size();
    // The fields as the last launches left them (host_view waits for them).
    const auto keys = flecsi_lite::host_view(particle_tree<D>::key(p));
    const auto x = flecsi_lite::host_view(f::position()(p));
    const auto m = flecsi_lite::host_view(f::mass()(p));
    const auto h = flecsi_lite::host_view(f::smoothing_length()(p));
    tree::gravity_options options;
    options.theta = settings.theta;
    options.relative_criterion = settings.criterion == gravity_criterion::relative;
    options.relative_tolerance = settings.relative_tolerance;
    std::vector<double> previous;  // |a_old| / G: the tree's units (G = 1)
    if (options.relative_criterion) {
      const auto a_old = flecsi_lite::host_view(f::acceleration(p));
      previous.resize(n);
      for (std::size_t a = 0; a < n; ++a) {
        double a2 = 0;
        for (int k = 0; k < D; ++k) a2 += a_old(a)[k] * a_old(a)[k];
        previous[a] = std::sqrt(a2) / settings.constant;
      }
    }
    tree::gravity_tree<D> gravity;
    gravity.build(keys.data(), x.data(), m.data(), h.data(), previous.empty() ? nullptr : previous.data(), n, options,
                  flecsi_lite::runtime::communicator());
    std::vector<vector<D>> acceleration(n);
    std::vector<double> potential(n);
    const tree::gravity_counts counts = physics::dispatch_kernel<D>(s.physics.kernel, [&](auto kernel) {
      using shape = typename decltype(kernel)::shape;
      return gravity.evaluate(softened_pair_field<shape>{}, acceleration.data(), potential.data());
    });
    record = {counts.node_interactions, counts.particle_interactions, gravity.imported_nodes(),
              gravity.imported_particles()};
    flecsi_lite::execute<detail::store_gravity<D>>(settings.constant, std::move(acceleration), std::move(potential),
                                                   f::gravity_acceleration(p), f::gravitational_potential(p));
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
