// The Evrard (1988, MNRAS 235, 911) adiabatic collapse for the SPH specialization: a gas sphere of
// mass M and radius R with rho = M / (2 pi R^2 r), u = 0.05 G M / R, at rest, gamma 5/3; particles
// of equal mass on a body-centred lattice stretched radially (spheres::stretch_to_inverse_r).
#pragma once

#include "sphere_lattice.hh"

#include "specialization/sph.hh"

#include "flecsi_lite/io.hh"
#include "flecsi_lite/runtime.hh"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace evrard {
namespace sph = flecsph::sph;

struct problem {
  std::int64_t particles = 20000;  ///< about this many particles (the lattice inside the ball holds a few more or less)
  double radius = 1;               ///< R
  double mass = 1;                 ///< M
  double thermal_energy = 0.05;    ///< u0 in units of G M / R
};

/// The problem keys, each bound to its member of `problem`.
const flecsi_lite::runtime::parameter_block<problem>& problem_parameters();

/// Checks what the keys imply (particle count, lengths, masses, energies); parameter_error naming
/// the keys otherwise.
void check_problem(const problem& problem, const sph::physics_settings& physics, double gravitational_constant);

/// The analytic energies of the continuous initial state: W0 = -2/3 G M^2 / R (for rho ~ 1/r,
/// M(<r) = M r^2 / R^2: W = -int G M(<r) dm / r), U0 = u0 M, K0 = 0.
struct initial_energies {
  double potential = 0, internal = 0;
  double total() const { return potential + internal; }
};
initial_energies analytic_energies(const problem& problem, double gravitational_constant);

/// This rank's block of the stretched lattice: positions R x, masses M / N, u0, at rest, and h
/// from the intended density: h = eta (m / rho(r))^(1/3) with r at least the radius holding one
/// particle's mass (the density pass iterates h from there). No fixed box: the tree's box follows
/// the particles. Collective.
template<int D>
void create_sphere(sph::simulation<D>& s, const problem& problem, double gravitational_constant) {
  static_assert(D == 3, "the Evrard sphere is three-dimensional");
  check_problem(problem, s.physics, gravitational_constant);
  const auto sites = spheres::ball_lattice(problem.particles);
  const auto block =
    flecsi_lite::io::block_slice(sites.size(), flecsi_lite::runtime::rank(), flecsi_lite::runtime::size());
  sph::create_particles(s, block.count);
  const double pi = std::acos(-1.0);
  const double mass = problem.mass / double(sites.size());
  const double u0 = problem.thermal_energy * gravitational_constant * problem.mass / problem.radius;
  const double innermost = problem.radius * std::sqrt(1.0 / double(sites.size()));  // M(<r) = m
  sph::initial_fields(s, [&](std::size_t i, sph::initial_particle<D>& p) {
    const std::uint64_t index = block.offset + i;
    const auto x = spheres::stretch_to_inverse_r(sites[index]);
    for (int k = 0; k < D; ++k) p.x[k] = problem.radius * x[static_cast<std::size_t>(k)];
    const double r = std::max(problem.radius * spheres::radius(x), innermost);
    p.rho = problem.mass / (2 * pi * problem.radius * problem.radius * r);
    p.id = index;
    p.m = mass;
    p.h = s.physics.eta * std::cbrt(mass / p.rho);
    p.u = u0;
    p.kind = sph::particle_kind::fluid;
  });
}

}  // namespace evrard
