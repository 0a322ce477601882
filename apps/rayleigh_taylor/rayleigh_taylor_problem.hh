// The Rayleigh-Taylor instability (2D) in the smooth set-up of Abel (2011, MNRAS 413, 271) and
// Hopkins (2015, MNRAS 450, 53) for the SPH specialization: in [0, W) x [0, H], periodic in x,
// density rho1 below and rho2 above the interface y_i = H / 2, joined by the logistic rho(y) =
// rho1 + (rho2 - rho1) / (1 + exp(-(y - y_i) / Delta)), in hydrostatic equilibrium under the
// uniform gravity -g along y: P(y) = P0 - g int_{y_i}^{y} rho, integrated exactly through the
// interface (ideal gas). One mode of wavelength W seeds it, the divergence-free velocity of the
// stream function psi = -(delta / k) sin(k x) f(y - y_i), k = 2 pi / W, f(e) = exp(-k sqrt(e^2 +
// Delta^2)): v_y = delta cos(k x) f, v_x = -(delta / k) sin(k x) f' (the sharp interface's
// eigenfunction exp(-k |e|), Chandrasekhar 1961, ch. X, smoothed over Delta). Walls: rows of fixed
// particles below y = 0 and above y = H that continue the lattice and the hydrostatic pressure.
// Equal-mass particles in rows of one count whose spacing follows the profile's density, started in
// the SPH equations' own equilibrium (discrete_equilibrium.hh).
#pragma once

#include "specialization/sph.hh"

#include "flecsi_lite/io.hh"
#include "flecsi_lite/runtime.hh"

#include <cmath>
#include <cstdint>
#include <vector>

namespace rayleigh_taylor {
namespace sph = flecsph::sph;

struct problem {
  std::int64_t per_side = 64;    ///< particles per unit length where rho = rho1 (m = rho1 / n^2)
  double width = 0.5;            ///< W: the period along x, also the wavelength of the seed
  double height = 1.0;           ///< H: the walls' distance
  double rho1 = 1, rho2 = 2;     ///< bottom and top densities
  double gravity = 0.5;          ///< g: the acceleration is -g along y
  double pressure = 2.5;         ///< P0 at the interface
  double smoothing = 0.025;      ///< Delta of the logistic profile
  double perturbation = 0.01;    ///< delta: the seed's largest v_y
  double lattice_density = 0;    ///< where the rows are as far apart as their particles; 0: rho1
  std::int64_t wall_layers = 0;  ///< rows of wall particles at each end; 0: the kernel's reach
};

/// The problem keys, each bound to its member of `problem`.
const flecsi_lite::runtime::parameter_block<problem>& problem_parameters();

/// Checks the counts and the lengths; throws parameter_error naming the keys otherwise.
void check_problem(const problem& problem, const sph::physics_settings& physics);

/// rho(y) of the logistic profile (any y: the walls take its values beyond [0, H]).
double density(double y, const problem& problem);

/// P(y) = P0 - g int_{y_i}^{y} rho (exact).
double hydrostatic_pressure(double y, const problem& problem);

/// The seed's velocity at (x, y).
sph::vector<2> seed_velocity(double x, double y, const problem& problem);

/// One row of particles: its y, its count, the shift of its first particle (in spacings) and
/// whether it is a wall row.
struct row {
  double y = 0;
  std::int64_t count = 0;
  double shift = 0;
  bool wall = false;
};

/// The particles' mass (the fluid's mass over its count).
double particle_mass(const problem& problem, const sph::physics_settings& physics);

/// The rows from the bottom walls to the top walls; the same on every rank.
std::vector<row> particle_rows(const problem& problem, const sph::physics_settings& physics);

/// The box periodic in x; along y it holds the walls with room to spare (keys only).
void set_domain(sph::simulation<2>& s, const problem& problem);

/// Fills this rank's block of the particles (row by row): equal masses, each row's h, rho and u =
/// P / ((gamma - 1) rho) of the discrete equilibrium (discrete_equilibrium.hh), the seed's velocity
/// on the fluid, walls at rest. Collective.
void create_particles(sph::simulation<2>& s, const problem& problem);

}  // namespace rayleigh_taylor
