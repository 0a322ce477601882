// The start in hydrostatic equilibrium as the SPH sums see it: at t = 0, after the first density
// sum and before the equation of state, every particle's u is set to P(y) / ((gamma - 1) rho_a)
// with rho_a its own SPH density and P(y) the exact hydrostatic pressure of the set-up. With u from
// the profile's rho(y) instead, the SPH density's smoothing of the interface (about 0.5% at h =
// 1.5 Delta) becomes a pressure error there whose waves (|v| ~ 0.01 by t = 0.2 at 32 particles per
// unit length, docs/rayleigh-taylor.md) are as large as the seed.
#pragma once

#include "rayleigh_taylor_problem.hh"

namespace rayleigh_taylor {

/// u_a = P(y_a) / ((gamma - 1) rho_a) for every particle, walls included.
template<int D>
void set_hydrostatic_energy(problem p, flecsph::physics::ideal_gas gas, sph::ro<sph::vector<D>> x,
                            sph::ro<double> rho, sph::rw<double> u) {
  flecsi_lite::forall(
    u.size(), [&](std::size_t a) { u(a) = gas.internal_energy(rho(a), hydrostatic_pressure(x(a)[1], p)); },
    "rayleigh_taylor::set_hydrostatic_energy");
}

/// The action: only in the force evaluation of the initial state (not after a restart, whose u
/// is the checkpoint's).
template<int D>
void start_hydrostatic(sph::simulation<D>& s, const problem& p) {
  if (!s.initializing || s.restarted) return;
  using f = sph::fields<D>;
  auto& particles = *s.particles;
  flecsi_lite::execute<set_hydrostatic_energy<D>>(p, s.physics.eos.ideal, f::position()(particles),
                                                  f::density(particles), f::internal_energy(particles));
}

}  // namespace rayleigh_taylor
