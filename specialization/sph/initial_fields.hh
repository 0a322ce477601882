// The particles of an SPH run before its first step: created with the tree settings the physics
// needs, and filled particle by particle by a problem through one task (initial_fields).
#pragma once

#include "specialization/sph/simulation.hh"

#include "flecsi_lite/data.hh"
#include "flecsi_lite/execution.hh"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <utility>

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

/// What a problem sets of one initial particle: position, velocity, id, mass, smoothing length,
/// kind, density (an initial guess) and specific internal energy. Each starts at zero (kind
/// fluid); every other field starts at zero too (omega is computed with the density before
/// anything reads it).
template<int D>
struct initial_particle {
  vector<D> x{}, v{};
  std::uint64_t id = 0;
  double m = 0, h = 0;
  particle_kind kind = particle_kind::fluid;
  double rho = 0, u = 0;
};

/// fill(i, particle) for owned particle i of this rank.
template<int D>
using initial_fill = std::function<void(std::size_t, initial_particle<D>&)>;

namespace detail {
template<class T>
using initial_accessor = typename flecsi_lite::field<T>::template accessor<flecsi_lite::wo>;

/// The task: every owned particle from a fresh initial_particle that `fill` sets (write only).
template<int D>
void set_initial_fields(const initial_fill<D>& fill, initial_accessor<vector<D>> x, initial_accessor<vector<D>> v,
                        initial_accessor<std::uint64_t> id, initial_accessor<double> m, initial_accessor<double> h,
                        initial_accessor<particle_kind> kind, initial_accessor<double> rho,
                        initial_accessor<double> u) {
  for (std::size_t i = 0; i < x.owned_size(); ++i) {
    initial_particle<D> p;
    fill(i, p);
    x(i) = p.x;
    v(i) = p.v;
    id(i) = p.id;
    m(i) = p.m;
    h(i) = p.h;
    kind(i) = p.kind;
    rho(i) = p.rho;
    u(i) = p.u;
  }
}
} // namespace detail

/// Sets the initial fields of this rank's particles (after create_particles) in one task with
/// write privileges on them, so that the executor knows they changed; returns when it has run
/// (`fill` may refer to the caller's locals). The calls come in order i = 0, 1, ... on one thread.
///
///   sph::initial_fields(s, [&](std::size_t i, sph::initial_particle<D>& p) { p.x = ...; p.m = ...; });
template<int D, class Fill>
void initial_fields(simulation<D>& s, Fill&& fill) {
  using f = fields<D>;
  auto& p = *s.particles;
  const initial_fill<D> function(std::forward<Fill>(fill));
  flecsi_lite::execute<detail::set_initial_fields<D>>(function, f::position()(p), f::velocity(p), f::id()(p),
                                                      f::mass()(p), f::smoothing_length()(p), f::kind(p),
                                                      f::density(p), f::internal_energy(p))
    .wait();
}

} // namespace flecsph::sph
