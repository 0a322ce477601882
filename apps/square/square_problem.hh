// The square test (Saitoh & Makino 2013, ApJ 768, 44; Hopkins 2013, MNRAS 428, 2840, and 2015,
// MNRAS 450, 53) for the SPH specialization: in the periodic unit box [0, 1)^2 a square
// [1/4, 3/4]^2 of density 4 in gas of density 1, both at P = 2.5 (gamma 5/3) and at rest. The exact
// solution is static; a scheme with a spurious surface tension at the contact discontinuity
// (standard SPH: the pressure blip where the density is smoothed but u is not) rounds the square
// towards a circle. Equal-mass particles on two cell-centre lattices, n per side outside and 2n per
// unit length inside (spacing ratio 2, density ratio 4), as SWIFT's
// examples/HydroTests/SquareTest_2D/makeIC.py: only the contact then drives motion (a glass would
// add its own noise). The comparison is made on the output by tests/validation/check_square.py.
#pragma once

#include "specialization/sph.hh"

#include "flecsi_lite/io.hh"
#include "flecsi_lite/runtime.hh"

#include <cmath>
#include <cstdint>
#include <vector>

namespace square {
namespace sph = flecsph::sph;

struct problem {
  std::int64_t per_side = 64;  ///< n: outer lattice particles per side of the unit box (a multiple of 4)
  double square_density = 4;
  double ambient_density = 1;
  double pressure = 2.5;
};

/// The problem keys, each bound to its member of `problem`.
const flecsi_lite::runtime::parameter_block<problem>& problem_parameters();

/// Checks the count, the lattices and the energies; throws parameter_error naming the keys otherwise.
void check_problem(const problem& problem, const sph::physics_settings& physics);

/// Particles per side of the square's lattice: n sqrt(rho_square / rho_ambient) / 2 (equal masses).
std::int64_t square_per_side(const problem& problem);

/// A site of either lattice: position and whether it belongs to the square.
struct site {
  double x = 0, y = 0;
  bool in_square = false;
};

/// Every site, the ambient lattice's (outside the square) first, row by row, then the square's:
/// the particle of id k sits at sites[k] on any number of ranks.
std::vector<site> lattice_sites(const problem& problem);

/// The periodic unit box, after check_problem.
inline void set_periodic_box(sph::simulation<2>& s, const problem& problem) {
  check_problem(problem, s.physics);
  flecsi_lite::topology::ntree::box<2> box;
  box.lo.fill(0.0);
  box.hi.fill(1.0);
  s.tree_settings.fixed_box = box;
  s.tree_settings.periodic.fill(true);
}

/// Fills this rank's block of the sites: mass 1 / n^2 for all, h = eta times the own lattice's
/// spacing, at rest, u = P / ((gamma - 1) rho) of the own phase. Collective.
inline void create_lattices(sph::simulation<2>& s, const problem& problem) {
  set_periodic_box(s, problem);
  const auto sites = lattice_sites(problem);
  const auto block =
    flecsi_lite::io::block_slice(sites.size(), flecsi_lite::runtime::rank(), flecsi_lite::runtime::size());
  sph::create_particles(s, block.count);
  const double mass = problem.ambient_density / double(problem.per_side * problem.per_side);
  sph::initial_fields(s, [&](std::size_t i, sph::initial_particle<2>& p) {
    const std::uint64_t index = block.offset + i;
    const site& here = sites[index];
    const double rho = here.in_square ? problem.square_density : problem.ambient_density;
    p.id = index;
    p.x = {here.x, here.y};
    p.m = mass;
    p.h = s.physics.eta * std::sqrt(mass / rho);
    p.kind = sph::particle_kind::fluid;
    p.rho = rho;
    p.u = s.physics.eos.ideal.internal_energy(rho, problem.pressure);
  });
}

}  // namespace square
