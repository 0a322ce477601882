// The particles of an SPH run before its first step: created with the tree settings the
// physics needs, and the host views through which a problem (or the initial-data reader) fills
// the fields of this rank's particles.
#pragma once

#include "specialization/sph/simulation.hh"

#include "flecsi_lite/data.hh"
#include "flecsi_lite/execution.hh"

#include <cstdint>
#include <memory>

namespace flecsph::sph {

/// Creates the particles of `s` with `local_count` owned particles here (fields zero): the tree's
/// reach is the kernel support plus the search margin, its ghosts reach the skin beyond. Collective.
template<int D>
void create_particles(simulation<D>& s, std::size_t local_count) {
  s.tree_settings.support = physics::kernel_support * (1.0 + s.physics.search_margin);
  s.tree_settings.ghost_reach_factor = 1.0 + s.physics.distribution_skin;
  s.neighbours = {};
  s.particles = std::make_unique<particle_tree<D>>(s.tree_settings, local_count);
}

/// Host views of the fields that initial particles set, for filling this rank's block after
/// create_particles (every other field starts at zero; kind zero is fluid, and omega is computed
/// with the density before anything reads it).
template<int D>
struct initial_views {
  template<class T>
  using view = typename flecsi_lite::data::field_storage<T>::view_type;

  explicit initial_views(particle_tree<D>& p)
    : x(flecsi_lite::host_view(fields<D>::position()(p))), v(flecsi_lite::host_view(fields<D>::velocity(p))),
      id(flecsi_lite::host_view(fields<D>::id()(p))), m(flecsi_lite::host_view(fields<D>::mass()(p))),
      h(flecsi_lite::host_view(fields<D>::smoothing_length()(p))), kind(flecsi_lite::host_view(fields<D>::kind(p))),
      rho(flecsi_lite::host_view(fields<D>::density(p))), u(flecsi_lite::host_view(fields<D>::internal_energy(p))) {}

  view<vector<D>> x, v;
  view<std::uint64_t> id;
  view<double> m, h;
  view<particle_kind> kind;
  view<double> rho, u;
};

} // namespace flecsph::sph
