// Particle sets for the SPH task tests: jittered lattices in a periodic or open box with
// pseudo-random velocities and internal energies, loaded into an ntree<D> with the SPH fields,
// and a direct O(N^2) evaluation of the kernel sums to compare the tasks with.
#pragma once

#include "specialization/sph/step/driver.hh"

#include "flecsi_lite/execution.hh"

#include <cmath>
#include <cstdint>
#include <vector>

namespace sph_test {
namespace sph = flecsph::sph;
namespace tree = flecsi_lite::topology::ntree;

/// A number in [-1, 1) from (id, salt), the same on every platform (splitmix64).
inline double hashed_unit(std::uint64_t id, std::uint64_t salt) {
  std::uint64_t z = id * 0x9e3779b97f4a7c15ull + salt * 0xbf58476d1ce4e5b9ull + 0x94d049bb133111ebull;
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
  z ^= z >> 31;
  return double(z >> 11) * 0x1.0p-52 - 1.0;
}

struct lattice {
  int per_side = 8;      ///< particles per side of the unit box
  bool periodic = true;  ///< periodic on every axis, else an open box
  double rho0 = 1.0;
  double u0 = 1.0;
  double jitter = 0.0;         ///< displacement in units of the spacing (uniform in [-j, j])
  double velocity = 0.0;       ///< random velocity amplitude
  double energy_spread = 0.0;  ///< relative random variation of u
};

/// Creates the particles of `s` (one rank owns them all before distribute) on `shape`.
template<int D>
void load_lattice(sph::simulation<D>& s, const lattice& shape) {
  std::size_t count = 1;
  for (int k = 0; k < D; ++k) count *= static_cast<std::size_t>(shape.per_side);
  const double spacing = 1.0 / shape.per_side;
  const double mass = shape.rho0 * std::pow(spacing, D);
  if (shape.periodic) {
    tree::box<D> unit;
    unit.lo.fill(0.0);
    unit.hi.fill(1.0);
    s.tree_settings.fixed_box = unit;
    s.tree_settings.periodic.fill(true);
  }
  sph::create_particles(s, flecsi_lite::runtime::rank() == 0 ? count : 0);
  sph::initial_fields(s, [&](std::size_t i, sph::initial_particle<D>& p) {
    std::size_t rest = i;
    for (int k = 0; k < D; ++k) {
      const double cell = double(rest % shape.per_side);
      rest /= shape.per_side;
      p.x[k] = (cell + 0.5 + shape.jitter * hashed_unit(i, 1 + k)) * spacing;
      p.v[k] = shape.velocity * hashed_unit(i, 11 + k);
    }
    p.id = 1000 + 7 * i;  // ids need not be contiguous
    p.m = mass;
    p.h = s.physics.eta * spacing;
    p.u = shape.u0 * (1.0 + shape.energy_spread * hashed_unit(i, 21));
    p.kind = sph::particle_kind::fluid;
  });
}

/// The shortest image of x_a - x_b (periodic unit box) or the plain difference.
template<int D>
sph::vector<D> image_separation(const sph::vector<D>& a, const sph::vector<D>& b, bool periodic) {
  sph::vector<D> r;
  for (int k = 0; k < D; ++k) {
    r[k] = a[k] - b[k];
    if (periodic) r[k] -= std::round(r[k]);
  }
  return r;
}

template<int D>
double norm(const sph::vector<D>& r) {
  double r2 = 0;
  for (int k = 0; k < D; ++k) r2 += r[k] * r[k];
  return std::sqrt(r2);
}

}  // namespace sph_test
