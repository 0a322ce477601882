// The vocabulary of SPH tasks: accessors to particle fields named by their privileges (FleCSI's
// ro / wo / rw, data/privilege.hh), so that a task's signature says what it reads and writes:
//
//   template<int D>
//   void cooling(double dt, sph::ro<double> rho, sph::rw<double> u);          // owned particles only
//   double smallest_h(sph::ro_with_ghosts<double> h);                         // owned and ghosts
//   flecsi_lite::execute<cooling<D>>(s.dt, f::density(p), f::internal_energy(p));
#pragma once

#include "specialization/sph/model/fields.hh"

#include "flecsi_lite/data.hh"
#include "flecsi_lite/execution.hh"

namespace flecsph::sph {

/// Any accessor: privileges on the owned particles and on the ghosts (copies of other ranks'
/// particles within reach); the executor derives dependencies and ghost copies from them.
template<class T, flecsi_lite::privilege Owned, flecsi_lite::privilege Ghost = flecsi_lite::na>
using accessor = flecsi_lite::accessor<T, Owned, Ghost>;

/// Reads the owned particles' values (per-particle tasks).
template<class T>
using ro = accessor<T, flecsi_lite::ro>;
/// Writes the owned particles' values without reading them.
template<class T>
using wo = accessor<T, flecsi_lite::wo>;
/// Reads and updates the owned particles' values.
template<class T>
using rw = accessor<T, flecsi_lite::rw>;
/// Reads owned and ghost values: what a pair sum over a neighbour list needs of a neighbour b.
/// The executor copies the ghosts first when the owned values changed since the last copy.
template<class T>
using ro_with_ghosts = accessor<T, flecsi_lite::ro, flecsi_lite::ro>;
/// Reads the values of a pair task's neighbours: owned only (Ghost = na), for the launch over
/// the interior targets that runs while the ghosts travel, or owned and ghosts (Ghost = ro), for
/// the launch over the boundary targets (neighbourhood::targets).
template<class T, flecsi_lite::privilege Ghost>
using ro_neighbours = accessor<T, flecsi_lite::ro, Ghost>;

}  // namespace flecsph::sph
