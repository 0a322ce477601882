// The fields weakly compressible SPH adds to those of sph::fields<D> (in memory only, so that the
// gas problems' files are unchanged): drho/dt, rho at the half step, the walls' prescribed velocity.
#pragma once

#include "specialization/sph/fields.hh"

namespace flecsph::fluid {

template<int D>
using vector = sph::vector<D>;

template<int D>
struct fluid_fields {
  template<class T>
  using definition = typename sph::particle_tree<D>::template definition<T>;
  /// drho/dt of the last force evaluation (continuity equation with delta-SPH diffusion).
  static inline const definition<double> density_rate{"fluid_density_rate"};
  static inline const definition<double> density_half{"fluid_density_half"};  ///< leapfrog half step
  /// A wall particle's own (prescribed) velocity: zero for fixed walls, the lid's for Couette. Its
  /// `velocity` field holds the extrapolated no-slip velocity 2 v_w - v~ (Adami et al. 2012 eq. 22).
  static inline const definition<vector<D>> wall_velocity{"fluid_wall_velocity"};
};

} // namespace flecsph::fluid
