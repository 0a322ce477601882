// The Gresho-Chan (1990, Int. J. Numer. Methods Fluids 11, 621) vortex for the SPH
// specialization, in the set-up of Springel (2010, MNRAS 401, 791, sec. 8.2) and Hopkins (2015,
// MNRAS 450, 53): a steady vortex of uniform density 1 (gamma 5/3) in the periodic box
// [-1/2, 1/2]^2, v_phi = 5 r (r < 0.2), 2 - 5 r (0.2 <= r < 0.4), 0 beyond, held by the pressure
// P = 5 + 12.5 r^2, 9 + 12.5 r^2 - 20 r + 4 ln(5 r), 3 + 4 ln 2 in the same zones. Every exact
// state is steady: the error of v_phi at t = 1 is the scheme's (viscosity, noise). The comparison
// is made on the output by tests/validation/check_gresho.py and apps/gresho/plot_gresho.py.
#pragma once

#include "specialization/sph.hh"

#include "flecsi_lite/io.hh"
#include "flecsi_lite/runtime.hh"

#include <cmath>
#include <cstdint>

namespace gresho {
namespace sph = flecsph::sph;

struct problem {
  std::int64_t per_side = 64;  ///< lattice particles per side of the box [-1/2, 1/2]^2
};

/// The problem keys, each bound to its member of `problem`.
const flecsi_lite::runtime::parameter_block<problem>& problem_parameters();

/// Checks the particle count and spacing; throws parameter_error naming the keys otherwise.
void check_problem(const problem& problem, const sph::physics_settings& physics);

/// The exact azimuthal velocity and pressure at radius r.
inline double azimuthal_velocity(double r) { return r < 0.2 ? 5.0 * r : (r < 0.4 ? 2.0 - 5.0 * r : 0.0); }
inline double pressure(double r) {
  if (r < 0.2) return 5.0 + 12.5 * r * r;
  if (r < 0.4) return 9.0 + 12.5 * r * r - 20.0 * r + 4.0 * std::log(5.0 * r);
  return 3.0 + 4.0 * std::log(2.0);
}

/// The periodic box [-1/2, 1/2]^2, after check_problem.
inline void set_periodic_box(sph::simulation<2>& s, const problem& problem) {
  check_problem(problem, s.physics);
  flecsi_lite::topology::ntree::box<2> box;
  box.lo.fill(-0.5);
  box.hi.fill(0.5);
  s.tree_settings.fixed_box = box;
  s.tree_settings.periodic.fill(true);
}

/// Fills this rank's block of the square lattice (cell centres): masses and h whose SPH density is
/// 1 on the lattice, the exact v and u = P / ((gamma - 1) rho). Collective.
inline void create_lattice(sph::simulation<2>& s, const problem& problem) {
  const auto n = static_cast<std::uint64_t>(problem.per_side);
  const auto block = flecsi_lite::io::block_slice(n * n, flecsi_lite::runtime::rank(), flecsi_lite::runtime::size());
  set_periodic_box(s, problem);
  sph::create_particles(s, block.count);
  const double spacing = 1.0 / double(problem.per_side);
  const auto particle = sph::density_consistent_particle<2>(s.physics, 1.0, spacing * spacing, [&](double h) {
    return sph::lattice_kernel_sum<2>(s.physics.kernel, h, spacing, spacing, 0.0);
  });
  sph::initial_fields(s, [&](std::size_t i, sph::initial_particle<2>& p) {
    const std::uint64_t index = block.offset + i;
    p.id = index;
    p.x[0] = (double(index % n) + 0.5) * spacing - 0.5;
    p.x[1] = (double(index / n) + 0.5) * spacing - 0.5;
    const double r = std::hypot(p.x[0], p.x[1]);
    const double v = azimuthal_velocity(r);
    p.v[0] = r > 0 ? -v * p.x[1] / r : 0.0;
    p.v[1] = r > 0 ? v * p.x[0] / r : 0.0;
    p.m = particle.mass;
    p.h = particle.h;
    p.kind = sph::particle_kind::fluid;
    p.rho = 1.0;
    p.u = s.physics.eos.ideal.internal_energy(1.0, pressure(r));
  });
}

}  // namespace gresho
