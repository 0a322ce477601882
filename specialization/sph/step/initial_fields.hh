// The particles of an SPH run before its first step: created with the tree settings the physics
// needs, and filled particle by particle by a problem through one task (initial_fields); and the
// mass and h at which the SPH density sum of a lattice equals the intended density.
#pragma once

#include "specialization/physics/kernels.hh"
#include "specialization/sph/model/simulation.hh"

#include "flecsi_lite/data.hh"
#include "flecsi_lite/execution.hh"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <memory>
#include <utility>

namespace flecsph::sph {

/// sum_j W(|x_j - x_i|, h) over the sites x_j of a layered lattice around one of its sites x_i
/// (itself included): layers `along` apart on x, each a square lattice of spacing `across` on the
/// transverse axes, odd layers shifted by `shift` across along each of them (0.5: body-centred).
/// Every site of such a lattice has the same sum; it is summed in a fixed order.
template<int D>
double lattice_kernel_sum(physics::kernel_type kernel, double h, double along, double across = 0, double shift = 0) {
  return physics::dispatch_kernel<D>(kernel, [&](auto w) {
    const double reach = physics::kernel_support * h;
    const auto layers = static_cast<long>(std::ceil(reach / along)) + 1;
    const auto sites = D == 1 ? 0L : static_cast<long>(std::ceil(reach / across)) + 1;
    double sum = 0;
    for (long n = -layers; n <= layers; ++n) {
      const double x = double(n) * along, offset = (n % 2 != 0) ? shift : 0.0;
      for (long j = -sites; j <= sites; ++j) {
        const double y = D > 1 ? (double(j) + offset) * across : 0.0;
        for (long k = D == 3 ? -sites : 0; k <= (D == 3 ? sites : 0); ++k) {
          const double z = D == 3 ? (double(k) + offset) * across : 0.0;
          sum += w.value(std::sqrt(x * x + y * y + z * z), h);
        }
      }
    }
    return sum;
  });
}

/// The mass and smoothing length of the particles of a uniform lattice (`volume` per particle)
/// whose SPH density m sum_j W(h) is `rho`, with h = eta (m / rho)^(1/D): m = rho / sum_j W(h) at
/// the fixed point of h. With m = rho volume instead, the cubic spline at eta 1.2 sums a density
/// 0.18% high (1D), which scales the whole solution. `kernel_sum(h)` is the lattice's sum.
struct lattice_particle {
  double mass = 0, h = 0;
};
template<int D, class KernelSum>
lattice_particle density_consistent_particle(const physics_settings& physics, double rho, double volume,
                                             KernelSum&& kernel_sum) {
  lattice_particle p{rho * volume, physics.eta * std::pow(volume, 1.0 / D)};
  for (int iteration = 0; iteration < 100; ++iteration) {  // contracts fast: S(h) varies slowly
    p.mass = rho / kernel_sum(p.h);
    const double h = physics.eta * std::pow(p.mass / rho, 1.0 / D);
    const bool converged = std::fabs(h - p.h) <= 1e-15 * p.h;
    p.h = h;
    if (converged) break;
  }
  return p;
}

/// Creates the particles of `s` with `local_count` owned particles here (fields zero): the tree's
/// reach is the kernel support plus the search margin, its ghosts reach the skin beyond. Collective.
template<int D>
void create_particles(simulation<D>& s, std::size_t local_count) {
  s.tree_settings.support = physics::kernel_support * (1.0 + s.physics.search_margin);
  s.tree_settings.ghost_reach_factor = 1.0 + s.physics.distribution_skin;
  s.tree_settings.order = s.physics.key_order;
  s.tree_settings.balancing = s.physics.balance;
  s.tree_settings.work_weight = s.physics.balance == tree::balance::work ? &fields<D>::work : nullptr;
  s.neighbours.host() = {};
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
}  // namespace detail

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
                                                      f::mass()(p), f::smoothing_length()(p), f::kind(p), f::density(p),
                                                      f::internal_energy(p))
    .wait();
}

}  // namespace flecsph::sph
