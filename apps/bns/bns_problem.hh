// Neutron stars as Newtonian n = 1 polytropes (P = K rho^2; Chandrasekhar 1939, ch. IV): the
// Lane-Emden star rho = rho_c sin(x) / x, x = pi r / R, with R = sqrt(pi K / (2 G)) (so
// K = 2 G R^2 / pi) and rho_c = pi M / (4 R^3); its particles on a body-centred lattice stretched
// radially so that the enclosed mass follows m(r) = M (sin x - x cos x) / pi; and the binary of two
// relaxed stars read from a single star's H5Part file, with the Roche-lobe check of a stable
// setup (Eggleton 1983, ApJ 268, 368).
#pragma once

#include "sphere_lattice.hh"

#include "specialization/sph.hh"

#include "flecsi_lite/runtime.hh"

#include <cstdint>
#include <string>

namespace bns {
namespace sph = flecsph::sph;

/// A single star (made from the lattice, or read as initial data) or a binary of two stars read
/// from a relaxed single star's file.
enum class setup { star, binary };
const flecsi_lite::runtime::name_table<setup>& setup_names();

/// Omega of the corotating frame and the release: Kepler's for point masses, or the one that
/// balances the stars' measured mean accelerations (tides included), updated every relaxation step.
enum class omega_rule { kepler, forces };
const flecsi_lite::runtime::name_table<omega_rule>& omega_rule_names();

struct problem {
  setup kind = setup::star;
  std::int64_t particles = 5000;  ///< about this many particles in a lattice star
  double mass = 1;                ///< M of the (first) star
  double companion_mass = 1;      ///< M of the second star (binary)
  double radius = 1;              ///< R of every star (n = 1: R does not depend on M at fixed K)
  std::string star_file;          ///< binary: the relaxed single star (its last step)
  double separation = 4;          ///< binary: distance a of the stars' centres
  bool stable_orbit = true;       ///< binary: refuse a separation at which a star fills its Roche lobe
  omega_rule orbit_omega = omega_rule::kepler;
  /// Damped relaxation (times in units of t_dyn = sqrt(R^3 / (G M))): at most relaxation_time, at
  /// least relaxation_min_time, until K / |W| < relaxation_tolerance; damping a -= v / damping_time.
  double relaxation_time = 0;
  double relaxation_min_time = 2;
  double relaxation_tolerance = 1e-4;
  double damping_time = 0.3;
  double observer_distance = 1;  ///< d of the strain (on the z axis)
  double speed_of_light = 1;     ///< c of the strain and of the radiation reaction
  /// Binary: the 2.5PN point-mass radiation reaction on the stars after the release, until their
  /// separation falls below radiation_reaction_cutoff R (contact).
  bool radiation_reaction = false;
  double radiation_reaction_cutoff = 2;
  /// G and c from the unit keys (unit_*_in_cgs) and their CGS values instead of the keys
  /// gravitational_constant and speed_of_light.
  bool physical_constants = false;
  /// Binary: the folder of cached relaxed stars (bns_star_cache.hh; empty: star_file), and the
  /// relaxation of a star made for it (in units of t_dyn; the tolerance is relaxation_tolerance).
  std::string star_cache;
  double star_relaxation_time = 30;
  double star_relaxation_min_time = 12;
  double star_damping_time = 1;
};

const flecsi_lite::runtime::parameter_block<problem>& problem_parameters();

/// Lane-Emden n = 1 in physical units: rho(r) (0 beyond R), the fraction of M inside r, and its
/// inverse (bisection to round-off).
double central_density(double mass, double radius);
double lane_emden_density(double r, double mass, double radius);
double enclosed_fraction(double r, double radius);
double radius_of_fraction(double fraction, double radius);
/// K = 2 G R^2 / pi (from R = sqrt(pi K / (2 G))).
double polytropic_constant(double radius, double gravitational_constant);
/// sqrt(R^3 / (G M)).
double dynamical_time(double mass, double radius, double gravitational_constant);
/// Eggleton's (1983) Roche-lobe radius over the separation of a star of mass m with companion m'
/// (q = m / m'): 0.49 q^(2/3) / (0.6 q^(2/3) + ln(1 + q^(1/3))); 0.379 for equal masses.
double roche_lobe_fraction(double mass, double companion);
/// Kepler: Omega = sqrt(G (M1 + M2) / a^3).
double kepler_omega(const problem& problem, double gravitational_constant);

/// G and c in the code units of the unit keys: G = G_cgs M_u T_u^2 / L_u^3, c = c_cgs T_u / L_u
/// (CODATA 2018: G = 6.67430e-8 cm^3 g^-1 s^-2, c = 2.99792458e10 cm/s).
struct code_constants {
  double gravitational_constant = 1, speed_of_light = 1;
};
code_constants physical_constants_in_code_units(double mass_in_cgs, double length_in_cgs, double time_in_cgs);

/// The checks of the keys and of what they imply (parameter_error naming the keys): n = 1 (the
/// exponent 2), K derived (polytropic_constant not set), gravity on, a binary's stars apart and,
/// with stable_orbit, outside their Roche lobes. `polytropic_constant_set`: the key came from the
/// file or the command line.
void check_problem(const problem& problem, const sph::physics_settings& physics, bool polytropic_constant_set);

/// This rank's block of a lattice star of N particles at the origin, at rest, u on the polytrope.
void create_star(sph::simulation<3>& s, const problem& problem);

/// The particles of the first star in the binary (ids below it) and in the star file.
std::uint64_t star_file_particles(const problem& problem);

/// The binary: the star file's particles (sorted by id, centred on their centre of mass, scaled
/// homologously to R and each star's M) twice, the first star (ids 0 .. N-1) at x = -a M2 / M,
/// the second (ids N .. 2N-1) at x = a M1 / M, at rest; u, h and rho scaled with them.
void create_binary(sph::simulation<3>& s, const problem& problem);

}  // namespace bns
