// bns: Newtonian neutron stars as n = 1 polytropes with SPH and self-gravity (Rasio & Shapiro
// 1992, ApJ 401, 226; Rosswog 2015, Living Rev. Comput. Astrophys. 1, 1): a single star relaxed
// with velocity damping and u on the polytrope, written as H5Part initial data; a binary of two
// relaxed stars, relaxed in the corotating frame (centrifugal term and damping, Kepler's Omega),
// then given the rigid velocities Omega x r and released; each star's centre of mass, the
// separation, the orbital phase and the quadrupole strain h+, hx in the statistics file; with
// radiation_reaction, the 2.5PN point-mass radiation reaction on the stars until contact, its
// energy and angular momentum losses and the balance E + E_radiated (bns_radiation_reaction.hh).
//
//   bns apps/bns/single_star.par                     # writes the relaxed star bns_star.h5part
//   mpirun -np 2 bns apps/bns/binary_stable.par      # reads it; the orbit at a = 4 R
#include "bns_diagnostics.hh"
#include "bns_problem.hh"
#include "bns_radiation_reaction.hh"
#include "bns_star_cache.hh"

#include "specialization/sph.hh"

#include "flecsi_lite/app.hh"
#include "flecsi_lite/runtime.hh"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <sstream>
#include <string>
#include <vector>

namespace {
using namespace flecsi_lite;
namespace sph = flecsph::sph;
using bns::vec;
using f = sph::fields<3>;

/// The relaxation's extra acceleration of the last force evaluation (memory only), removed at release.
const sph::particle_tree<3>::definition<vec> relaxation_acceleration{"bns_relaxation_acceleration"};

struct bns_run : sph::app_state<3> {
  bns::problem problem;
  double G = 1, K = 0, dynamical_time = 0, omega = 0;
  double force_omega = 0;            ///< Omega of the stars' mean accelerations at the last relaxation step
  std::uint64_t first_star_end = 0;  ///< ids below: the first star (all of a single star)
  bool relaxing = false;
  double release_time = -1;  ///< when the relaxation ended (-1: not during this run)
  // The checks: after the relaxation (or from the start without one).
  bool monitoring = false;
  double radius_50 = 0, radius_90 = 0, largest_radius_drift = 0;
  double first_density_error = -1, last_density_error = 0;
  double first_separation = 0, last_separation = 0, largest_separation_drift = 0;
  double first_lz = 0, largest_lz_drift = 0;
  double monitored_from = 0;
  bns::radiation_reaction_record radiation_reaction;
  double first_balance = 0, largest_balance_drift = 0;  ///< E + E_radiated from the release on
};

/// a += -v / tau + Omega^2 (x, y, 0) - (the star's mean of those and of the forces): the damped
/// relaxation, in the corotating frame for a binary, with the stars' centres held.
void add_relaxation_acceleration(double inverse_damping, double omega2, std::array<vec, 2> held,
                                 std::uint64_t first_star_end, sph::ro<std::uint64_t> id,
                                 sph::ro<sph::particle_kind> kind, sph::ro<vec> x, sph::ro<vec> v, sph::rw<vec> a,
                                 sph::wo<vec> extra) {
  flecsi_lite::forall(
    x.size(),
    [&](std::size_t p) {
      vec added{};
      if (kind(p) == sph::particle_kind::fluid) {
        const vec& hold = held[static_cast<std::size_t>(bns::star_of(id(p), first_star_end))];
        for (int k = 0; k < 3; ++k) added[k] = -v(p)[k] * inverse_damping - hold[k] + (k < 2 ? omega2 * x(p)[k] : 0.0);
      }
      for (int k = 0; k < 3; ++k) a(p)[k] += added[k];
      extra(p) = added;
    },
    "bns::relaxation_acceleration");
}

void relaxation_forces(bns_run& s) {
  if (!s.relaxing) return;
  auto& p = *s.particles;
  std::array<vec, 2> held{};
  double omega2 = 0;
  if (s.problem.kind == bns::setup::binary) {
    const auto stars = bns::measure_stars(s, s.first_star_end);  // the forces alone
    // The Omega that balances them for circular motion of the centres: -(A2 - A1).(X2 - X1) / |X2 - X1|^2.
    double along = 0, d2 = 0;
    for (int k = 0; k < 3; ++k) {
      const double d = stars.centre[1][k] - stars.centre[0][k];
      along -= (stars.acceleration[1][k] - stars.acceleration[0][k]) * d;
      d2 += d * d;
    }
    s.force_omega = along > 0 ? std::sqrt(along / d2) : 0.0;
    if (s.problem.orbit_omega == bns::omega_rule::forces && s.force_omega > 0) s.omega = s.force_omega;
    omega2 = s.omega * s.omega;
    for (int star = 0; star < 2; ++star)
      for (int k = 0; k < 3; ++k)
        held[star][k] = stars.acceleration[star][k] + (k < 2 ? omega2 * stars.centre[star][k] : 0.0);
  }
  flecsi_lite::execute<add_relaxation_acceleration>(1 / (s.problem.damping_time * s.dynamical_time), omega2, held,
                                                    s.first_star_end, f::id()(p), f::kind(p), f::position()(p),
                                                    f::velocity(p), f::acceleration(p), relaxation_acceleration(p));
}

void polytrope_energy(double K, sph::ro<sph::particle_kind> kind, sph::ro<double> rho, sph::rw<double> u) {
  flecsi_lite::forall(
    u.size(),
    [&](std::size_t p) {
      if (kind(p) == sph::particle_kind::fluid) u(p) = K * rho(p);  // K rho^(Gamma - 1) / (Gamma - 1), Gamma = 2
    },
    "bns::polytrope_energy");
}

void keep_on_polytrope(bns_run& s) {
  if (!s.relaxing) return;
  auto& p = *s.particles;
  flecsi_lite::execute<polytrope_energy>(s.K, f::kind(p), f::density(p), f::internal_energy(p));
}

/// The release: v = Omega z x r, plus with `infall` each star's share of the inspiral's radial
/// velocity (infall[star], the same for all its particles).
void corotate(double omega, bool with_infall, std::array<vec, 2> infall, std::uint64_t first_star_end,
              sph::ro<std::uint64_t> id, sph::ro<sph::particle_kind> kind, sph::ro<vec> x, sph::ro<vec> extra,
              sph::wo<vec> v, sph::rw<vec> a) {
  flecsi_lite::forall(
    x.size(),
    [&](std::size_t p) {
      v(p) = kind(p) == sph::particle_kind::fluid ? vec{-omega * x(p)[1], omega * x(p)[0], 0.0} : vec{};
      if (with_infall && kind(p) == sph::particle_kind::fluid)
        for (int k = 0; k < 3; ++k) v(p)[k] += infall[static_cast<std::size_t>(bns::star_of(id(p), first_star_end))][k];
      for (int k = 0; k < 3; ++k) a(p)[k] -= extra(p)[k];
    },
    "bns::corotate");
}

/// After a step of the relaxation: ends it once K / |W| < relaxation_tolerance (after
/// relaxation_min_time) or at relaxation_time. A single star's run ends there (its output is the
/// relaxed star); a binary is set rotating rigidly with Omega about the centre of mass (the origin).
void relaxation_check(bns_run& s) {
  if (!s.relaxing) return;
  const auto totals = sph::measure_conserved(s);
  const double ratio = totals.kinetic / std::fabs(totals.potential);
  const double tau = s.time / s.dynamical_time;
  const bool relaxed = tau >= s.problem.relaxation_min_time && ratio < s.problem.relaxation_tolerance;
  if (!relaxed && tau < s.problem.relaxation_time) return;
  s.relaxing = false;
  s.release_time = s.time;
  std::ostringstream line;
  line << std::setprecision(5) << "bns: relaxation " << (relaxed ? "converged" : "stopped at relaxation_time")
       << " at t = " << s.time << " = " << tau << " t_dyn (step " << s.step << "): K / |W| = " << ratio;
  if (s.problem.kind == bns::setup::star) {
    s.finished = true;
    line << "; the relaxed star is the last step of '" << s.files.output_file << "'";
  } else {
    auto& p = *s.particles;
    // With the radiation reaction, the quasi-circular inspiral's radial velocity of Peters (1964),
    // adot = -beta / a^3, shared as the centres' positions are (X_i adot / a): no eccentricity from
    // releasing a shrinking orbit at rest in the radial direction.
    std::array<vec, 2> infall{};
    if (s.problem.radiation_reaction) {
      const auto stars = bns::measure_stars(s, s.first_star_end);
      double d2 = 0;
      for (int k = 0; k < 3; ++k)
        d2 += (stars.centre[1][k] - stars.centre[0][k]) * (stars.centre[1][k] - stars.centre[0][k]);
      const double separation = std::sqrt(d2);
      const double adot = -flecsph::physics::peters_rate(s.G, stars.mass[0], stars.mass[1], s.problem.speed_of_light) /
                          (separation * separation * separation);
      for (int star = 0; star < 2; ++star)
        for (int k = 0; k < 3; ++k) infall[star][k] = adot / separation * stars.centre[star][k];
      line << "; with Peters' radial velocity da/dt = " << adot;
    }
    flecsi_lite::execute<corotate>(s.omega, s.problem.radiation_reaction, infall, s.first_star_end, f::id()(p),
                                   f::kind(p), f::position()(p), relaxation_acceleration(p), f::velocity(p),
                                   f::acceleration(p));
    line << "; released with Omega = " << s.omega << " ("
         << (s.problem.orbit_omega == bns::omega_rule::kepler ? "Kepler" : "the forces") << "), orbital period "
         << 2 * std::acos(-1.0) / s.omega << "; Kepler " << bns::kepler_omega(s.problem, s.G)
         << ", the stars' mean forces " << s.force_omega;
  }
  log::info() << line.str();
}

std::vector<sph::statistics_column> extra_columns(const bns_run& s) {
  std::vector<sph::statistics_column> columns;
  const auto add = [&](const std::string& name, const std::string& meaning, const std::string& unit) {
    columns.push_back({name, meaning, unit});
  };
  const int stars = s.problem.kind == bns::setup::binary ? 2 : 1;
  for (int star = 1; star <= stars; ++star)
    for (const char* axis : {"x", "y", "z"})
      add("star" + std::to_string(star) + "_" + axis,
          "centre of mass of star " + std::to_string(star) + " (its particles at the start: ids)", "L");
  if (stars == 2) {
    add("separation", "distance of the stars' centres of mass", "L");
    add("orbital_phase", "atan2 of the separation vector's y and x (star 2 - star 1), in (-pi, pi]", "1");
  } else {
    add("half_mass_radius", "radius about the centre of mass holding half the mass", "L");
    add("radius_90", "radius holding 90% of the mass", "L");
    add("density_error", "mean over particles inside 0.9 R of |rho - rho_Lane-Emden| / rho_c", "1");
  }
  add("h_plus", "strain h+ on the z axis at observer_distance, quadrupole formula", "1");
  add("h_cross", "strain hx on the z axis at observer_distance", "1");
  add("relaxing", "1 during the damped relaxation, 0 after", "1");
  if (s.problem.radiation_reaction) {
    add("radiation_reaction_power", "energy per time the radiation reaction removed at the last force evaluation",
        "M L^2 T^-3");
    add("quadrupole_luminosity", "Peters-Mathews quadrupole luminosity of the stars' centres then", "M L^2 T^-3");
    add("radiated_energy", "energy removed by the radiation reaction since the start", "M L^2 T^-2");
    add("radiated_angular_momentum", "z angular momentum removed by the radiation reaction", "M L^2 T^-1");
    add("energy_balance", "total + radiated_energy: conserved", "M L^2 T^-2");
    add("radiation_reaction_on", "1 while it acts (released, before contact), 0 otherwise", "1");
  }
  return columns;
}

std::vector<double> extra_values(bns_run& s) {
  const auto stars = bns::measure_stars(s, s.first_star_end);
  std::vector<double> values;
  const int count = s.problem.kind == bns::setup::binary ? 2 : 1;
  for (int star = 0; star < count; ++star)
    values.insert(values.end(), stars.centre[star].begin(), stars.centre[star].end());
  if (count == 2) {
    const double dx = stars.centre[1][0] - stars.centre[0][0], dy = stars.centre[1][1] - stars.centre[0][1],
                 dz = stars.centre[1][2] - stars.centre[0][2];
    values.push_back(std::sqrt(dx * dx + dy * dy + dz * dz));
    values.push_back(std::atan2(dy, dx));
  } else {
    const auto profile = bns::measure_profile(s, s.problem, stars.centre[0]);
    values.insert(values.end(), {profile.half_mass_radius, profile.radius_90, profile.density_error});
  }
  const auto h =
    flecsph::physics::strain_on_z_axis(stars.rate, s.G, s.problem.speed_of_light, s.problem.observer_distance);
  values.insert(values.end(), {h.plus, h.cross, s.relaxing ? 1.0 : 0.0});
  if (s.problem.radiation_reaction) {
    const auto& rr = s.radiation_reaction;
    values.insert(values.end(), {rr.power, rr.luminosity, rr.radiated_energy, rr.radiated_angular_momentum,
                                 sph::measure_conserved(s).total + rr.radiated_energy, rr.applied ? 1.0 : 0.0});
  }
  return values;
}

/// Every step once the relaxation is over: the drifts the checks bound.
void monitor(bns_run& s) {
  if (s.relaxing) return;
  const auto stars = bns::measure_stars(s, s.first_star_end);
  const auto drift = [](double value, double reference) { return std::fabs(value / reference - 1); };
  if (s.problem.kind == bns::setup::star) {
    const auto profile = bns::measure_profile(s, s.problem, stars.centre[0]);
    if (!s.monitoring) {
      s.radius_50 = profile.half_mass_radius, s.radius_90 = profile.radius_90;
      s.first_density_error = profile.density_error;
    }
    s.largest_radius_drift = std::max(
      {s.largest_radius_drift, drift(profile.half_mass_radius, s.radius_50), drift(profile.radius_90, s.radius_90)});
    s.last_density_error = profile.density_error;
  } else {
    double d2 = 0;
    for (int k = 0; k < 3; ++k)
      d2 += (stars.centre[1][k] - stars.centre[0][k]) * (stars.centre[1][k] - stars.centre[0][k]);
    const auto totals = sph::measure_conserved(s);
    // With the radiation reaction, Lz + L_radiated is what is conserved.
    const double lz = totals.angular_momentum[2] + s.radiation_reaction.radiated_angular_momentum;
    const double balance = totals.total + s.radiation_reaction.radiated_energy;
    if (!s.monitoring) s.first_separation = std::sqrt(d2), s.first_lz = lz, s.first_balance = balance;
    s.last_separation = std::sqrt(d2);
    s.largest_separation_drift = std::max(s.largest_separation_drift, drift(std::sqrt(d2), s.first_separation));
    if (s.first_lz != 0) s.largest_lz_drift = std::max(s.largest_lz_drift, drift(lz, s.first_lz));
    s.largest_balance_drift = std::max(s.largest_balance_drift, std::fabs(balance - s.first_balance));
  }
  if (!s.monitoring) s.monitored_from = s.time;
  s.monitoring = true;
}

/// The angular momentum drift, or why there is none: with Lz0 = 0 (the stars were never set
/// rotating, as with relaxation_time = 0) |Lz / Lz0 - 1| is not a number.
std::string lz_drift_text(const bns_run& s) {
  std::ostringstream text;
  text << std::setprecision(5);
  if (s.first_lz != 0)
    text << s.largest_lz_drift;
  else
    text << "n/a (Lz0 = 0 at t = " << s.monitored_from
         << ": the stars do not orbit; only a relaxation, relaxation_time > 0, sets them rotating)";
  return text.str();
}

void report(bns_run& s) {
  std::ostringstream line;
  line << std::setprecision(5) << "bns: t = " << s.time << " = " << s.time / s.dynamical_time
       << " t_dyn (t_dyn = " << s.dynamical_time << ", K = " << s.K << ")";
  if (!s.monitoring)
    line << "; still relaxing";
  else if (s.problem.kind == bns::setup::star)
    line << "; from t = " << s.monitored_from << ": half-mass radius " << s.radius_50 << ", 90% radius " << s.radius_90
         << ", largest radius drift " << s.largest_radius_drift
         << "; mean |rho - rho_LE| / rho_c inside 0.9 R: " << s.first_density_error << " at the start, "
         << s.last_density_error << " at the end";
  else
    line << "; from t = " << s.monitored_from << " (" << (s.time - s.monitored_from) * s.omega / (2 * std::acos(-1.0))
         << " orbits): separation " << s.first_separation << " -> " << s.last_separation << ", largest |a / a0 - 1| "
         << s.largest_separation_drift << ", largest |Lz / Lz0 - 1| " << lz_drift_text(s)
         << (s.problem.radiation_reaction ? " (Lz + L_radiated)" : "");
  log::info() << line.str();
  if (s.problem.radiation_reaction && s.monitoring) {
    const auto& rr = s.radiation_reaction;
    std::ostringstream out;
    out << std::setprecision(5) << "bns: radiation reaction: radiated energy " << rr.radiated_energy
        << ", angular momentum " << rr.radiated_angular_momentum << "; largest |E + E_radiated - (E + E_radiated)_0| "
        << s.largest_balance_drift << " = " << s.largest_balance_drift / std::fabs(rr.radiated_energy)
        << " of the radiated energy; "
        << (rr.switched_off ? "switched off at contact, t = " + std::to_string(rr.switched_off_at)
                            : std::string("still on at the end"));
    log::info() << out.str();
  }
}

/// --check-equilibrium D,R (single star) and --check-orbit S,L (binary): exit status 1 when exceeded.
int check(const bns_run& s, const app::check_values& checks) {
  bool pass = true;
  if (checks.has("check-equilibrium")) {
    const auto& b = checks.bounds("check-equilibrium");
    const bool ok =
      s.monitoring && s.first_density_error <= b[0] && s.last_density_error <= b[0] && s.largest_radius_drift <= b[1];
    if (!ok)
      log::error() << "bns: check failed: density error " << s.first_density_error << ", " << s.last_density_error
                   << " (bound " << b[0] << "), radius drift " << s.largest_radius_drift << " (bound " << b[1] << ")";
    pass = pass && ok;
  }
  if (checks.has("check-energy-balance")) {
    const double bound = checks.bounds("check-energy-balance")[0];
    const double radiated = s.radiation_reaction.radiated_energy;
    const bool ok = s.monitoring && radiated > 0 && s.largest_balance_drift <= bound * radiated;
    if (!ok)
      log::error() << "bns: check failed: largest |E + E_radiated - (E + E_radiated)_0| " << s.largest_balance_drift
                   << " against " << bound << " of the radiated energy " << radiated;
    pass = pass && ok;
  }
  if (checks.has("check-orbit")) {
    const auto& b = checks.bounds("check-orbit");
    const bool ok = s.monitoring && s.first_lz != 0 && s.largest_separation_drift <= b[0] && s.largest_lz_drift <= b[1];
    if (!ok)
      log::error() << "bns: check failed: separation drift " << s.largest_separation_drift << " (bound " << b[0]
                   << "), angular momentum drift " << lz_drift_text(s) << " (bound " << b[1] << ")";
    pass = pass && ok;
  }
  return pass ? 0 : 1;
}

int run(const app::run_context& context, const bns::star_cache_entry* making = nullptr);

/// Relaxes the star of `entry` into its file: a single-star run of the same parameters with the
/// star_* relaxation settings, on all ranks; throws when it fails.
void make_cached_star(const app::run_context& context, const bns::star_cache_entry& entry, double dynamical_time) {
  const auto& p = context.parameters();
  const double longest = p.get<double>("star_relaxation_time");
  const auto number = [](double value) {
    std::ostringstream text;
    text << std::setprecision(17) << value;
    return text.str();
  };
  // The run's own parameter file and --set assignments (so that every key keeps its origin), then these.
  std::vector<std::string> overrides = context.options().all("set");
  const std::vector<std::string> star = {"setup=star",
                                         "output_file=" + entry.path,
                                         "statistics_file=none",
                                         "restart_file=none",
                                         "initial_data=none",
                                         "star_cache=none",
                                         "radiation_reaction=false",
                                         "max_steps=0",
                                         "relaxation_time=" + number(longest),
                                         "relaxation_min_time=" + number(p.get<double>("star_relaxation_min_time")),
                                         "damping_time=" + number(p.get<double>("star_damping_time")),
                                         "end_time=" + number(longest * dynamical_time),
                                         "output_every=" + number(longest * dynamical_time)};
  overrides.insert(overrides.end(), star.begin(), star.end());
  const auto star_parameters = runtime::parameters::load(p.schema(), context.options().get("parameters"), overrides);
  static app::definition frame;
  frame.program = context.program();
  const app::run_context star_context(frame, star_parameters, context.options());
  if (run(star_context, &entry) != 0)
    throw std::runtime_error("bns: star cache: relaxing the star into '" + entry.path + "' failed");
}

/// star_cache: the binary's star file, made first when the cache lacks it; said and recorded.
void use_star_cache(bns_run& s, const app::run_context& context) {
  const auto entry = bns::star_cache_entry_for(context.parameters(), s.G, s.problem.star_cache);
  std::ostringstream hash;
  hash << std::hex << std::setw(16) << std::setfill('0') << entry.hash;
  if (std::filesystem::exists(entry.path)) {
    log::info() << "bns: star cache: reusing '" << entry.path << "' (key hash " << hash.str() << ")";
  } else {
    log::info() << "bns: star cache: no star for these keys (hash " << hash.str() << ") in '" << s.problem.star_cache
                << "': relaxing one into '" << entry.path << "'";
    if (runtime::rank() == 0) std::filesystem::create_directories(s.problem.star_cache);
    make_cached_star(context, entry, s.dynamical_time);
    log::info() << "bns: star cache: made '" << entry.path << "'";
  }
  s.problem.star_file = entry.path;
  s.description["star_file_used"] = entry.path;
  s.description["star_cache_hash"] = hash.str();
}

int run(const app::run_context& context, const bns::star_cache_entry* making) {
  bns_run s;
  sph::configure(s, context);
  s.problem = bns::problem_parameters().read(context.parameters());
  if (s.problem.physical_constants) {
    for (const char* key : {"gravitational_constant", "speed_of_light"})
      if (context.parameters().origin(key) != "default")
        throw runtime::parameter_error(std::string("bns: physical_constants = true derives ") + key +
                                       " from the unit keys: do not set it");
    const auto& u = s.output_keys.units;
    const auto constants = bns::physical_constants_in_code_units(u.mass_in_cgs, u.length_in_cgs, u.time_in_cgs);
    s.physics.gravity.constant = constants.gravitational_constant;
    s.problem.speed_of_light = constants.speed_of_light;
  }
  if (s.problem.radiation_reaction && s.problem.kind != bns::setup::binary)
    throw runtime::parameter_error("bns: radiation_reaction = true needs setup = binary (it acts on two stars)");
  if (s.problem.radiation_reaction && s.physics.individual_time_steps())
    throw runtime::parameter_error(
      "bns: radiation_reaction = true with time_steps = individual: the stars' reaction is evaluated at every "
      "system step for every particle; use time_steps = global");
  bns::check_problem(s.problem, s.physics, context.parameters().origin("polytropic_constant") != "default");
  s.G = s.physics.gravity.constant;
  s.K = bns::polytropic_constant(s.problem.radius, s.G);
  s.physics.eos.polytrope.polytropic_constant = s.K;
  s.dynamical_time = bns::dynamical_time(s.problem.mass, s.problem.radius, s.G);
  s.omega = s.problem.kind == bns::setup::binary ? bns::kepler_omega(s.problem, s.G) : 0.0;
  s.relaxing = s.problem.relaxation_time > 0 && s.files.restart_file.empty();
  if (s.relaxing && s.physics.individual_time_steps())
    throw runtime::parameter_error(
      "bns: time_steps = individual with relaxation_time = " + std::to_string(s.problem.relaxation_time) +
      ": the relaxation damps every particle's velocity in every step, which "
      "individual steps do not take; relax with time_steps = global, or set "
      "relaxation_time = 0");
  // The star's mass, radius and G stay as root attributes: a binary set-up reads them back from
  // the star file (create_binary); K and the dynamical time are what the keys imply.
  s.description = {{"star_mass", s.problem.mass},
                   {"star_radius", s.problem.radius},
                   {"polytropic_constant", s.K},
                   {"gravitational_constant", s.G},
                   {"dynamical_time", s.dynamical_time}};
  if (making) {
    for (const auto& [key, value] : making->keys) s.description["cache_" + key] = value;
    std::ostringstream hash;
    hash << std::hex << std::setw(16) << std::setfill('0') << making->hash;
    s.description["cache_hash"] = hash.str();
  }
  if (s.problem.kind == bns::setup::binary && !s.problem.star_cache.empty()) use_star_cache(s, context);
  if (s.problem.radiation_reaction) {
    s.description["companion_mass"] = s.problem.companion_mass;
    s.description["speed_of_light"] = s.problem.speed_of_light;
  }
  s.extra_statistics_columns = extra_columns(s);
  s.extra_statistics = [&s] { return extra_values(s); };
  auto m = sph::make_app_control_model<bns_run>({[](bns_run&) {},
                                                 [](bns_run& state) {
                                                   if (state.problem.kind == bns::setup::star)
                                                     bns::create_star(state, state.problem);
                                                   else
                                                     bns::create_binary(state, state.problem);
                                                 }});
  // Star membership by id: the binary's first star holds the star file's particles.
  m.action("initial_data", "membership",
           [](bns_run& state) {
             state.first_star_end = state.problem.kind == bns::setup::binary ? bns::star_file_particles(state.problem)
                                                                             : state.particles->global_size();
           })
    .after("particles");
  // At t = 0 the polytrope's u joins the force evaluation before the pressure; in every step it
  // follows the kick (below).
  m.action("force_evaluation", "polytrope",
           [](bns_run& state) {
             if (state.initializing) keep_on_polytrope(state);
           })
    .after("gravity");
  m.action("force_evaluation", "relaxation", relaxation_forces).after("forces");
  bns::place_radiation_reaction(m);
  m.action("advance", "polytrope", keep_on_polytrope).after("kick");
  m.action("analyze", "relaxation_check",
           [](bns_run& state) {
             relaxation_check(state);
             monitor(state);
           })
    .after("conserved_quantities");
  m.action("initialize", "monitor", monitor).after("diagnostics");
  m.action("finalize", "report", report);
  return context.execute(m, s, [&context](const bns_run& state) { return check(state, context.checks()); });
}
}  // namespace

int main(int argc, char** argv) {
  sph::app_definition definition;
  definition.program = "bns";
  definition.summary =
    "Newtonian neutron stars (n = 1 polytropes) with SPH and self-gravity: a relaxed star, a binary.";
  definition.declare_parameters = [](runtime::parameter_schema& schema) { bns::problem_parameters().declare(schema); };
  definition.physics_defaults.eos.type = flecsph::physics::eos_type::polytropic;
  definition.physics_defaults.eos.ideal.gamma = 2;
  definition.physics_defaults.conductivity = 0;
  definition.physics_defaults.gravity.enabled = true;
  definition.run_defaults.end_time = 100;
  definition.run_defaults.progress_every = 100;
  definition.run_defaults.diagnostics_every = 100;
  definition.file_defaults.output_file = "bns.h5part";
  definition.file_defaults.output_every = 1;
  definition.file_defaults.checkpoint_file = "bns.checkpoint.h5part";
  definition.checks = {
    {"check-equilibrium",
     {"D", "R"},
     "single star: exit 1 unless the mean density error inside 0.9 R stays within D (at the start and the end) and "
     "the half-mass and 90% radii within R of their values after the relaxation"},
    {"check-orbit",
     {"S", "L"},
     "binary: exit 1 unless the separation stays within S and Lz (plus the radiated Lz) within L of their values "
     "at release"},
    {"check-energy-balance",
     {"B"},
     "binary with radiation_reaction: exit 1 unless E + E_radiated stays within B times the radiated energy of its "
     "value at release"}};
  definition.run = [](const app::run_context& context) { return run(context); };
  return sph::app_main(argc, argv, definition);
}
