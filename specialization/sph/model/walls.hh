// Whether a run has wall particles: the walls' accumulators (boundary_impulse, boundary_work)
// take memory and go to the checkpoints only then (the "walls" feature, simulation::has_walls).
#pragma once

#include "specialization/sph/model/fields.hh"
#include "specialization/sph/model/simulation.hh"
#include "specialization/sph/model/tasks.hh"

#include "flecsi_lite/execution.hh"

#include <cstddef>
#include <cstdint>

namespace flecsph::sph {
namespace detail {
inline std::uint64_t wall_count(ro<particle_kind> kind) {
  std::uint64_t count = 0;
  for (std::size_t a = 0; a < kind.size(); ++a) count += kind(a) == particle_kind::wall;
  return count;
}
}  // namespace detail

/// Collective: the wall particles of every rank.
template<int D>
std::uint64_t count_walls(simulation<D>& s) {
  return flecsi_lite::reduce<detail::wall_count, flecsi_lite::reduction::sum>(fields<D>::kind(*s.particles)).get();
}

/// Collective: sets s.has_walls from the particles (created, or read from initial data), before
/// any task reads the walls' accumulators.
template<int D>
void find_walls(simulation<D>& s) {
  s.has_walls = count_walls(s) > 0;
}
}  // namespace flecsph::sph
