// The surge front of a dam break, one definition for every check, plot and document
// (docs/fluid-flow.md): the largest x of a fluid particle near the floor (at most front_height
// above it) that has at least two fluid neighbours within 2 dx, plus dx / 2. The neighbour
// condition keeps an isolated droplet ahead of the tip from being the front (a pair of droplets
// alone, each other's only neighbour, is not either); dx / 2 is the edge of the particle's own
// cell, so the initial front is the column's face exactly.
#pragma once

#include "specialization/sph/model/neighbourhood.hh"
#include "specialization/sph/model/tasks.hh"

#include "flecsi_lite/execution.hh"

#include <algorithm>
#include <limits>

namespace flecsph::fluid {

/// The front's inputs that are not fields.
struct surge_front_settings {
  double floor_y = 0;          ///< the floor's surface
  double height = 0;           ///< candidates lie at most this far above it
  double neighbour_reach = 0;  ///< 2 dx
};

/// The largest x of the owned fluid particles that qualify (-max double when none does); the
/// neighbour lists hold every particle within the kernel support 2 h >= 2 dx, ghosts included.
template<int D>
double surge_front_task(sph::neighbours_ro<D> neighbours_object, surge_front_settings settings,
                        sph::ro_with_ghosts<sph::vector<D>> x, sph::ro_with_ghosts<sph::particle_kind> kind) {
  const sph::neighbourhood<D>& neighbours = *neighbours_object;
  const sph::neighbour_walk<D> walk(neighbours);
  const double reach2 = settings.neighbour_reach * settings.neighbour_reach;
  double front = -std::numeric_limits<double>::max();
  sph::vector<D> r;
  for (std::size_t a = 0; a < neighbours.size(); ++a) {
    if (kind(a) != sph::particle_kind::fluid || x(a)[1] - settings.floor_y > settings.height || x(a)[0] <= front)
      continue;
    int count = 0;
    const sph::neighbour_row<D> row = walk.row(a);
    for (std::size_t j = 0, end = row.size(); j < end && count < 2; ++j) {
      const std::size_t b = row.neighbour(j);
      if (kind(b) != sph::particle_kind::fluid) continue;
      const double r2 = row.separation(x(a), x(b), j, r);
      if (r2 > 0 && r2 < reach2) ++count;
    }
    if (count >= 2) front = x(a)[0];
  }
  return front;
}

}  // namespace flecsph::fluid
