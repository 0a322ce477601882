// The binary's measures, summed exactly over ranks (Demmel & Nguyen superaccumulator: the same bits
// on any number of ranks): each star's mass, centre of mass and mean acceleration (membership by
// particle id: ids below first_star_end are star 1), mean velocity, the second time derivative of the quadrupole
// for the strain (physics/gravitational_waves.hh), and a single star's radial profile (mass radii
// from particle counts, the mean density error against Lane-Emden inside 0.9 R).
#pragma once

#include "bns_problem.hh"

#include "specialization/physics.hh"
#include "specialization/sph.hh"

#include "flecsi_lite/execution.hh"
#include "flecsi_lite/util.hh"

#include <array>
#include <cmath>
#include <cstdint>

namespace bns {
using vec = sph::vector<3>;
using exact_sum = flecsi_lite::util::exact_sum;

/// Per star: sum m, sum m x, sum m v, sum m a; over all particles: sum m (2 v v + x a + a x).
struct star_sums {
  std::array<exact_sum, 2> mass;
  std::array<std::array<exact_sum, 3>, 2> moment, momentum, force;
  std::array<exact_sum, 6> rate;
  star_sums& operator+=(const star_sums& other) {
    for (int s = 0; s < 2; ++s) {
      mass[s] += other.mass[s];
      for (int k = 0; k < 3; ++k)
        moment[s][k] += other.moment[s][k], momentum[s][k] += other.momentum[s][k], force[s][k] += other.force[s][k];
    }
    for (int k = 0; k < 6; ++k) rate[k] += other.rate[k];
    return *this;
  }
};
struct star_sums_reduction {
  static star_sums combine(star_sums a, const star_sums& b) { return a += b; }
};

inline int star_of(std::uint64_t id, std::uint64_t first_star_end) { return id >= first_star_end ? 1 : 0; }

inline star_sums sum_stars(std::uint64_t first_star_end, sph::ro<std::uint64_t> id, sph::ro<sph::particle_kind> kind,
                           sph::ro<vec> x, sph::ro<vec> v, sph::ro<vec> a, sph::ro<double> m) {
  star_sums sums;
  for (std::size_t p = 0; p < x.size(); ++p) {
    if (kind(p) != sph::particle_kind::fluid) continue;
    const int s = star_of(id(p), first_star_end);
    sums.mass[s].add(m(p));
    for (int k = 0; k < 3; ++k) {
      sums.moment[s][k].add(m(p) * x(p)[k]);
      sums.momentum[s][k].add(m(p) * v(p)[k]);
      sums.force[s][k].add(m(p) * a(p)[k]);
    }
    const auto term = flecsph::physics::quadrupole_second_derivative(m(p), x(p), v(p), a(p));
    for (int k = 0; k < 6; ++k) sums.rate[k].add(term[k]);
  }
  return sums;
}

/// The values of star_sums: centres of mass, their velocities, mean accelerations, Ï_ij.
struct star_measures {
  std::array<double, 2> mass{};
  std::array<vec, 2> centre{}, velocity{}, acceleration{};
  flecsph::physics::symmetric_tensor rate{};
};

/// Collective: the measures with the current acceleration field.
inline star_measures measure_stars(sph::simulation<3>& s, std::uint64_t first_star_end) {
  using f = sph::fields<3>;
  auto& p = *s.particles;
  const auto sums =
    flecsi_lite::reduce<sum_stars, star_sums_reduction>(first_star_end, f::id()(p), f::kind(p), f::position()(p),
                                                        f::velocity(p), f::acceleration(p), f::mass()(p))
      .get();
  star_measures result;
  for (int star = 0; star < 2; ++star) {
    result.mass[star] = sums.mass[star].value();
    for (int k = 0; k < 3; ++k) {
      const double mass = result.mass[star] > 0 ? result.mass[star] : 1.0;
      result.centre[star][k] = sums.moment[star][k].value() / mass;
      result.velocity[star][k] = sums.momentum[star][k].value() / mass;
      result.acceleration[star][k] = sums.force[star][k].value() / mass;
    }
  }
  for (int k = 0; k < 6; ++k) result.rate[k] = sums.rate[k].value();
  return result;
}

/// A single star's profile about `centre`: particle counts in radial bins to r_max (equal masses:
/// the count is the mass, an integer, so its sum is exact), and the sum and count of
/// |rho - rho_LE(r)| / rho_c of the particles inside 0.9 R.
struct profile_sums {
  spheres::radial_mass counts;
  exact_sum error;
  std::uint64_t inside = 0;
};
struct profile_reduction {
  static profile_sums combine(profile_sums a, const profile_sums& b) {
    a.counts = spheres::radial_mass_reduction::combine(a.counts, b.counts);
    a.error += b.error;
    a.inside += b.inside;
    return a;
  }
};

inline profile_sums sum_profile(vec centre, double r_max, double mass, double radius, sph::ro<sph::particle_kind> kind,
                                sph::ro<vec> x, sph::ro<double> rho) {
  profile_sums sums;
  const double rho_c = central_density(mass, radius);
  for (std::size_t p = 0; p < x.size(); ++p) {
    if (kind(p) != sph::particle_kind::fluid) continue;
    const double r = spheres::radius({x(p)[0] - centre[0], x(p)[1] - centre[1], x(p)[2] - centre[2]});
    const auto bin = static_cast<long>(r / r_max * spheres::bin_count);
    if (bin >= spheres::bin_count)
      sums.counts.outside += 1;
    else
      sums.counts.mass[static_cast<std::size_t>(std::max(0L, bin))] += 1;
    if (r < 0.9 * radius) {
      sums.error.add(std::fabs(rho(p) - lane_emden_density(r, mass, radius)) / rho_c);
      ++sums.inside;
    }
  }
  return sums;
}

struct profile_measures {
  double half_mass_radius = 0, radius_90 = 0;
  double density_error = 0;  ///< mean |rho - rho_LE| / rho_c inside 0.9 R
};

/// Collective: the profile of a single star (all fluid particles) about `centre`.
inline profile_measures measure_profile(sph::simulation<3>& s, const problem& problem, const vec& centre) {
  using f = sph::fields<3>;
  auto& p = *s.particles;
  const double r_max = 2 * problem.radius;
  const auto sums = flecsi_lite::reduce<sum_profile, profile_reduction>(centre, r_max, problem.mass, problem.radius,
                                                                        f::kind(p), f::position()(p), f::density(p))
                      .get();
  profile_measures result;
  result.half_mass_radius = spheres::fraction_radius(sums.counts, r_max, 0.5);
  result.radius_90 = spheres::fraction_radius(sums.counts, r_max, 0.9);
  result.density_error = sums.inside ? sums.error.value() / double(sums.inside) : 0.0;
  return result;
}

}  // namespace bns
