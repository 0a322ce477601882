// The fields weakly compressible SPH adds to those of sph::fields<D>: drho/dt, rho at the half step,
// the walls' prescribed velocity. drho/dt and the walls' velocity are read by the next step, so
// they are in checkpoints (a fluid restart continues bitwise); rho at the half step is recomputed
// in every step. Only the fluid app declares them: the gas problems' files are unchanged.
#pragma once

#include "specialization/sph/model/fields.hh"

namespace flecsph::fluid {

template<int D>
using vector = sph::vector<D>;

template<int D>
struct fluid_fields {
  template<class T>
  using definition = typename sph::particle_tree<D>::template definition<T>;
  /// drho/dt of the last force evaluation (continuity equation with delta-SPH diffusion).
  static inline const definition<double> density_rate{"fluid_density_rate", sph::persist::restart()};
  static inline const definition<double> density_half{"fluid_density_half"};  ///< leapfrog half step
  /// A wall particle's own (prescribed) velocity: zero for fixed walls, the lid's for Couette. Its
  /// `velocity` field holds the extrapolated no-slip velocity 2 v_w - v~ (Adami et al. 2012 eq. 22).
  static inline const definition<vector<D>> wall_velocity{"fluid_wall_velocity",
                                                          sph::persist::as("wall_vx", "wall_vy", "wall_vz").restart()};
};

}  // namespace flecsph::fluid
