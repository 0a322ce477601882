// The Noh (1987, J. Comput. Phys. 72, 78) implosion for the SPH specialization: a cold, uniform
// gas (gamma 5/3) on a lattice moving at speed 1 towards the centre (a line in 2D, a point in 3D).
// A shock leaves the centre at r_s = t (gamma - 1) / 2 with the density rho0 ((gamma + 1) /
// (gamma - 1))^D behind it (16 in 2D, 64 in 3D); ahead of it rho0 (1 + t / r)^(D - 1). Particle
// codes overheat the centre ("wall heating": the density there stays below the exact value).
// The comparison is made on the output by tests/validation/check_noh.py and apps/noh/plot_noh.py.
#pragma once

#include "glass_tiling.hh"

#include "specialization/sph.hh"

#include "flecsi_lite/io.hh"
#include "flecsi_lite/runtime.hh"

#include <cmath>
#include <cstdint>

namespace noh {
namespace sph = flecsph::sph;

struct problem {
  int dimension = 2;
  std::int64_t per_side = 64;  ///< lattice particles per side of the box [-L/2, L/2]^D
  double side = 2.0;           ///< L: the gas starts in [-L/2, L/2]^D
  double rho0 = 1.0;
  double speed = 1.0;      ///< inflow speed
  double pressure = 1e-6;  ///< of the (nearly cold) gas
};

/// The problem keys, each bound to its member of `problem`.
const flecsi_lite::runtime::parameter_block<problem>& problem_parameters();

/// Checks what the keys imply in `dimension` dimensions (particle count, lengths, mass, energy);
/// throws parameter_error naming the keys otherwise.
void check_problem(const problem& problem, const sph::physics_settings& physics, int dimension);

/// An open domain (no periodic axis), after check_problem: the gas at the edge of the initial box
/// has no neighbours outside, so its density is low there, but it is cold (P = 1e-6), so its
/// pressure pushes nothing; the edge moves inward at the inflow speed and stays beyond r = L/2 - t
/// (0.4 at t = 0.6 with L = 2), far outside the shock at r = t/3.
template<int D>
void set_open_domain(sph::simulation<D>& s, const problem& problem) {
  check_problem(problem, s.physics, D);
  s.tree_settings.periodic.fill(false);
}

/// Fills this rank's block of the lattice (cell centres, so no particle sits at the centre):
/// masses and h whose SPH density is rho0 on the lattice, v = -speed x / |x|. With a `glass`
/// (initial_lattice = glass) the particles are the tiled glass's, of equal mass rho0 V / N. Collective.
template<int D>
void create_lattice(sph::simulation<D>& s, const problem& problem, const glass::tiling<D>* glass = nullptr) {
  std::uint64_t total = 1;
  for (int k = 0; k < D; ++k) total *= static_cast<std::uint64_t>(problem.per_side);
  const auto block = flecsi_lite::io::block_slice(total, flecsi_lite::runtime::rank(), flecsi_lite::runtime::size());
  set_open_domain(s, problem);
  sph::create_particles(s, block.count);
  const double spacing = problem.side / double(problem.per_side);
  const auto particle =
    glass ? glass->particle(s.physics, problem.rho0, spacing)
          : sph::density_consistent_particle<D>(s.physics, problem.rho0, std::pow(spacing, D), [&](double h) {
              return sph::lattice_kernel_sum<D>(s.physics.kernel, h, spacing, spacing, 0.0);
            });
  const double u = s.physics.eos.ideal.internal_energy(problem.rho0, problem.pressure);
  const auto n = static_cast<std::uint64_t>(problem.per_side);
  sph::initial_fields(s, [&](std::size_t i, sph::initial_particle<D>& p) {
    std::uint64_t index = block.offset + i;
    p.id = index;
    double r2 = 0;
    if (glass) p.x = glass->position(-0.5 * problem.side, problem.side, index);
    for (int k = 0; k < D; ++k, index /= n) {
      if (!glass) p.x[k] = (double(index % n) + 0.5) * spacing - 0.5 * problem.side;
      r2 += p.x[k] * p.x[k];
    }
    const double r = std::sqrt(r2);
    for (int k = 0; k < D; ++k) p.v[k] = -problem.speed * p.x[k] / r;
    p.m = particle.mass;
    p.h = particle.h;
    p.kind = sph::particle_kind::fluid;
    p.rho = problem.rho0;
    p.u = u;
  });
}

}  // namespace noh
