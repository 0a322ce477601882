// The fields of the SPH specialization on the ntree<D> topology (seed sec. 1.3): what each
// particle carries besides the topology's built-in position, id, mass and smoothing length h.
#pragma once

#include "flecsi_lite/data.hh"
#include "flecsi_lite/topology/ntree.hh"

#include <array>
#include <cstdint>

namespace flecsph::sph {

/// A vector in D dimensions (velocity, acceleration); positions are ntree's point<D>, the same type.
template<int D>
using vector = std::array<double, D>;

template<int D>
using particle_tree = flecsi_lite::topology::ntree::ntree<D>;

/// FLUID particles follow the equations of motion. WALL particles are fixed boundary particles
/// (Sod's reflecting ends): they enter every sum as neighbours, their density and pressure are
/// computed like the fluid's at their fixed h, but they are never moved or heated. The forces the
/// fluid exerts on them are accumulated (boundary_impulse, boundary_work) so that the totals of
/// fluid plus walls are conserved and can be checked.
enum class particle_kind : std::int32_t { fluid = 0, wall = 1 };

/// The fields of dimension D, declared once (fields are per topology type, ntree<D>).
template<int D>
struct fields {
  template<class T>
  using definition = typename flecsi_lite::field<T>::template definition<particle_tree<D>>;

  // The topology's own fields, named here so that tasks read as physics.
  static const auto& position() { return particle_tree<D>::position; }
  static const auto& id() { return particle_tree<D>::id; }
  static const auto& mass() { return particle_tree<D>::mass; }
  static const auto& smoothing_length() { return particle_tree<D>::smoothing_length; }

  static inline const definition<particle_kind> kind{"kind"};
  static inline const definition<vector<D>> velocity{"velocity"};             ///< v (predicted during a step)
  static inline const definition<vector<D>> velocity_half{"velocity_half"};   ///< v at the half step (leapfrog)
  static inline const definition<vector<D>> acceleration{"acceleration"};     ///< dv/dt, eq. (1.9)
  static inline const definition<double> density{"rho"};                      ///< eq. (1.3)
  static inline const definition<double> pressure{"P"};
  static inline const definition<double> sound_speed{"cs"};
  static inline const definition<double> internal_energy{"u"};                ///< specific
  static inline const definition<double> internal_energy_half{"u_half"};
  static inline const definition<double> internal_energy_rate{"du_dt"};       ///< eq. (1.8)
  static inline const definition<double> omega{"omega"};                      ///< grad-h factor (1 for fixed h)
  static inline const definition<double> pressure_term{"P_over_omega_rho2"};  ///< P / (Omega rho^2)
  static inline const definition<double> velocity_divergence{"div_v"};        ///< for the Balsara switch
  static inline const definition<double> velocity_curl{"curl_v"};             ///< |curl v|, same
  static inline const definition<double> balsara{"balsara"};                  ///< Balsara factor (1: off)
  /// Path length since the last distribution, and h then: when to distribute again.
  static inline const definition<double> drift{"drift"};
  static inline const definition<double> distributed_h{"distributed_h"};
  /// Accumulated (per unit mass) forces and heating the fluid exerted on a wall particle.
  static inline const definition<vector<D>> boundary_impulse{"boundary_impulse"};
  static inline const definition<double> boundary_work{"boundary_work"};
};

} // namespace flecsph::sph
