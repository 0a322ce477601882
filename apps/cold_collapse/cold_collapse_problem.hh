// The cold (pressureless) collapse of a uniform sphere for the SPH specialization: mass M, radius
// R, at rest, u tiny; every shell falls freely and reaches the centre at the free-fall time
// t_ff = (pi / 2) sqrt(R^3 / (2 G M)), its radius r = r0 x(t) with
// t / t_ff = (2 / pi) (arccos(sqrt(x)) + sqrt(x (1 - x))) (e.g. Binney & Tremaine 2008, sec. 2.2).
#pragma once

#include "sphere_lattice.hh"

#include "specialization/sph.hh"

#include "flecsi_lite/io.hh"
#include "flecsi_lite/runtime.hh"

#include <cmath>
#include <cstdint>

namespace cold_collapse {
namespace sph = flecsph::sph;

struct problem {
  std::int64_t particles = 10000;  ///< about this many particles
  double radius = 1;               ///< R
  double mass = 1;                 ///< M
  double thermal_energy = 1e-6;    ///< u in units of G M / R: pressure negligible before t_ff
  double mass_fraction = 0.9;      ///< the measured radius holds this fraction of the mass
  double compare_until = 0.9;      ///< compare with free fall up to this fraction of t_ff
};

/// The problem keys, each bound to its member of `problem`.
const flecsi_lite::runtime::parameter_block<problem>& problem_parameters();

/// Checks what the keys imply; parameter_error naming the keys otherwise.
void check_problem(const problem& problem, const sph::physics_settings& physics, double gravitational_constant);

/// t_ff = (pi / 2) sqrt(R^3 / (2 G M)).
double free_fall_time(const problem& problem, double gravitational_constant);

/// x = r / r0 of a freely falling shell at tau = t / t_ff in [0, 1] (bisection on the exact
/// relation, to round-off).
double free_fall_radius(double tau);

/// This rank's block of the lattice ball of radius R: masses M / N, at rest, u, h = eta (m / rho)^(1/3).
/// No fixed box: the tree's box follows the particles. Collective.
template<int D>
void create_sphere(sph::simulation<D>& s, const problem& problem, double gravitational_constant) {
  static_assert(D == 3, "the collapsing sphere is three-dimensional");
  check_problem(problem, s.physics, gravitational_constant);
  const auto sites = spheres::ball_lattice(problem.particles);
  const auto block =
    flecsi_lite::io::block_slice(sites.size(), flecsi_lite::runtime::rank(), flecsi_lite::runtime::size());
  sph::create_particles(s, block.count);
  const double pi = std::acos(-1.0);
  const double mass = problem.mass / double(sites.size());
  const double rho = problem.mass / (4.0 / 3.0 * pi * std::pow(problem.radius, 3));
  const double u = problem.thermal_energy * gravitational_constant * problem.mass / problem.radius;
  sph::initial_fields(s, [&](std::size_t i, sph::initial_particle<D>& p) {
    const std::uint64_t index = block.offset + i;
    for (int k = 0; k < D; ++k) p.x[k] = problem.radius * sites[index][static_cast<std::size_t>(k)];
    p.rho = rho;
    p.id = index;
    p.m = mass;
    p.h = s.physics.eta * std::cbrt(mass / rho);
    p.u = u;
    p.kind = sph::particle_kind::fluid;
  });
}

}  // namespace cold_collapse
