// The Kelvin-Helmholtz instability in the smooth set-up of McNally, Lyra & Passy (2012, ApJS 201,
// 18, eqs. 1-3) for the SPH specialization: in the periodic unit box, density 1 (|y - 1/2| > 1/4)
// and 2 (the middle band) moving at +0.5 and -0.5 along x, both smoothed over L = 0.025 by
// exponentials, at P = 2.5 (gamma 5/3), seeded by v_y = 0.01 sin(4 pi x). Equal-mass particles in
// rows of the profile's own density: each row holds n_x particles at spacing 1/n_x with n_x about
// 1 / sqrt(m / rho(y)) (locally isotropic), and its band of y holds exactly its mass (the inverse of
// the cumulative mass of rho(y)); alternate rows are shifted by half a spacing. The mode amplitude
// and its growth rate are measured on the output by tests/validation/check_kelvin_helmholtz.py.
#pragma once

#include "specialization/sph.hh"

#include "flecsi_lite/io.hh"
#include "flecsi_lite/runtime.hh"

#include <cmath>
#include <cstdint>
#include <vector>

namespace kelvin_helmholtz {
namespace sph = flecsph::sph;

struct problem {
  std::int64_t per_side = 64;  ///< particles per unit length where rho = rho1 (m = rho1 / n^2)
  double rho1 = 1, rho2 = 2;   ///< outer and middle-band densities
  double u1 = 0.5, u2 = -0.5;  ///< their x velocities
  double smoothing = 0.025;    ///< L of the exponential profiles
  double pressure = 2.5;
  double perturbation = 0.01;  ///< amplitude of v_y = A sin(4 pi x)
};

/// The problem keys, each bound to its member of `problem`.
const flecsi_lite::runtime::parameter_block<problem>& problem_parameters();

/// Checks the count and the lengths; throws parameter_error naming the keys otherwise.
void check_problem(const problem& problem, const sph::physics_settings& physics);

/// McNally's smoothed step of eqs. 1-2 between `outer` and `inner` at y in [0, 1).
double profile(double y, double outer, double inner, double smoothing);

/// The mass of the unit box under the profile (eqs. 1-2 integrated exactly).
double total_mass(const problem& problem);

/// One row of particles: its y, its count and the shift of its first particle (in spacings).
struct row {
  double y = 0;
  std::int64_t count = 0;
  double shift = 0;
};

/// The rows filling [0, 1) with the profile's mass; the same on every rank.
std::vector<row> particle_rows(const problem& problem);

/// The periodic unit box, after check_problem.
inline void set_periodic_box(sph::simulation<2>& s, const problem& problem) {
  check_problem(problem, s.physics);
  flecsi_lite::topology::ntree::box<2> box;
  box.lo.fill(0.0);
  box.hi.fill(1.0);
  s.tree_settings.fixed_box = box;
  s.tree_settings.periodic.fill(true);
}

/// Fills this rank's block of the particles (row by row): equal masses (the box's mass over the
/// count), h = eta sqrt(m / rho(y)), v = (v_x(y), A sin(4 pi x)), u = P / ((gamma - 1) rho(y)). Collective.
inline void create_particles(sph::simulation<2>& s, const problem& problem) {
  set_periodic_box(s, problem);
  const auto rows = particle_rows(problem);
  std::vector<std::int64_t> first(rows.size() + 1, 0);
  for (std::size_t r = 0; r < rows.size(); ++r) first[r + 1] = first[r] + rows[r].count;
  const auto total = static_cast<std::uint64_t>(first.back());
  const auto block = flecsi_lite::io::block_slice(total, flecsi_lite::runtime::rank(), flecsi_lite::runtime::size());
  sph::create_particles(s, block.count);
  const double mass = total_mass(problem) / double(total);
  const double pi = std::acos(-1.0);
  std::size_t r = 0;
  sph::initial_fields(s, [&](std::size_t i, sph::initial_particle<2>& p) {
    const auto index = static_cast<std::int64_t>(block.offset + i);
    while (first[r + 1] <= index) ++r;  // particles come in order of index
    const row& here = rows[r];
    const double x = (double(index - first[r]) + 0.5 + here.shift) / double(here.count);
    const double rho = profile(here.y, problem.rho1, problem.rho2, problem.smoothing);
    p.id = static_cast<std::uint64_t>(index);
    p.x = {x - std::floor(x), here.y};
    p.v = {profile(here.y, problem.u1, problem.u2, problem.smoothing),
           problem.perturbation * std::sin(4 * pi * p.x[0])};
    p.m = mass;
    p.h = s.physics.eta * std::sqrt(mass / rho);
    p.kind = sph::particle_kind::fluid;
    p.rho = rho;
    p.u = s.physics.eos.ideal.internal_energy(rho, problem.pressure);
  });
}

}  // namespace kelvin_helmholtz
