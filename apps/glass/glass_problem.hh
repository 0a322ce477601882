// The glass generator's problem: equal-mass particles at random positions in the periodic unit box
// [0, 1)^D, relaxed by damped SPH pressure forces at a uniform temperature (u held fixed) towards
// uniform density, as the glass makers of Gadget (White 1996, "Formation and evolution of
// galaxies", Les Houches) and SWIFT do with hydrodynamics: an irregular arrangement with no
// preferred direction and a small density scatter. The relaxation's loop is in glass.cc.
#pragma once

#include "specialization/sph.hh"

#include "flecsi_lite/io.hh"
#include "flecsi_lite/runtime.hh"

#include <cmath>
#include <cstdint>

namespace glass {
namespace sph = flecsph::sph;

struct problem {
  int dimension = 2;
  std::int64_t per_side = 32;  ///< N = per_side^D particles: mean spacing 1 / per_side
  std::int64_t seed = 1;       ///< of the random start
  double sound_speed = 1;      ///< of the isothermal gas (u = cs^2 / (gamma (gamma - 1)))
  double damping_time = 0.1;   ///< a -= v / damping_time
  /// The relaxation stops when the density scatter fell by less than this fraction over the last
  /// convergence_interval of time (or at end_time).
  double convergence_tolerance = 0.02;
  double convergence_interval = 0.5;
};

/// The problem keys, each bound to its member of `problem`.
const flecsi_lite::runtime::parameter_block<problem>& problem_parameters();

/// Checks the particle count and the lengths; throws parameter_error naming the keys otherwise.
void check_problem(const problem& problem, const sph::physics_settings& physics, int dimension);

/// A uniform deviate in [0, 1) from (seed, index, axis) alone (SplitMix64, Steele et al. 2014):
/// the same particle gets the same position on any number of ranks.
inline double uniform_deviate(std::uint64_t seed, std::uint64_t index, int axis) {
  std::uint64_t z =
    seed * 0x9e3779b97f4a7c15ULL + index * 0xbf58476d1ce4e5b9ULL + std::uint64_t(axis + 1) * 0x94d049bb133111ebULL;
  for (int round = 0; round < 2; ++round) {
    z += 0x9e3779b97f4a7c15ULL;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    z ^= z >> 31;
  }
  return double(z >> 11) * 0x1.0p-53;
}

/// The periodic unit box [0, 1)^D, after check_problem.
template<int D>
void set_periodic_box(sph::simulation<D>& s, const problem& problem) {
  check_problem(problem, s.physics, D);
  flecsi_lite::topology::ntree::box<D> box;
  box.lo.fill(0.0);
  box.hi.fill(1.0);
  s.tree_settings.fixed_box = box;
  s.tree_settings.periodic.fill(true);
}

/// The internal energy of the isothermal gas: c_s^2 = gamma (gamma - 1) u.
inline double internal_energy(const problem& problem, const sph::physics_settings& physics) {
  const double gamma = physics.eos.ideal.gamma;
  return problem.sound_speed * problem.sound_speed / (gamma * (gamma - 1));
}

/// Fills this rank's block of the N random particles: mass 1 / N (mean density 1), h = eta /
/// per_side, at rest, u of the isothermal gas. Collective.
template<int D>
void create_random(sph::simulation<D>& s, const problem& problem) {
  std::uint64_t total = 1;
  for (int k = 0; k < D; ++k) total *= static_cast<std::uint64_t>(problem.per_side);
  const auto block = flecsi_lite::io::block_slice(total, flecsi_lite::runtime::rank(), flecsi_lite::runtime::size());
  set_periodic_box(s, problem);
  sph::create_particles(s, block.count);
  const double u = internal_energy(problem, s.physics);
  const double h = s.physics.eta / double(problem.per_side);
  sph::initial_fields(s, [&](std::size_t i, sph::initial_particle<D>& p) {
    const std::uint64_t index = block.offset + i;
    p.id = index;
    for (int k = 0; k < D; ++k) p.x[k] = uniform_deviate(static_cast<std::uint64_t>(problem.seed), index, k);
    p.m = 1.0 / double(total);
    p.h = h;
    p.kind = sph::particle_kind::fluid;
    p.rho = 1.0;
    p.u = u;
  });
}

}  // namespace glass
