// The Sedov-Taylor point blast for the SPH specialization: energy E deposited with the kernel at
// the centre of a uniform, cold medium on a lattice in a periodic box, and the comparison with the
// similarity solution (Sedov 1959; Kamm & Timmes 2007): shock radius from the radial density peak.
#pragma once

#include "glass_tiling.hh"

#include "specialization/analytic.hh"
#include "specialization/sph.hh"

#include "flecsi_lite/io.hh"
#include "flecsi_lite/runtime.hh"

#include <array>
#include <cmath>
#include <cstdint>

namespace sedov {
namespace sph = flecsph::sph;

struct problem {
  int dimension = 3;
  std::int64_t per_side = 50;  ///< lattice particles per side of the box [-L/2, L/2]^D
  double side = 1.0;
  double energy = 1.0;  ///< E, deposited with the kernel around the centre
  double rho0 = 1.0;
  double background_pressure = 1e-6;
};

/// The problem keys, each bound to its member of `problem` (the physics keys are
/// sph::physics_parameters).
const flecsi_lite::runtime::parameter_block<problem>& problem_parameters();

/// Checks what the keys imply in `dimension` dimensions: a particle count of at most 2^40, a box,
/// spacing and h within the lengths the SPH tasks handle, and finite, positive masses and
/// energies; throws parameter_error naming the keys otherwise.
void check_problem(const problem& problem, const sph::physics_settings& physics, int dimension);

/// The domain: the periodic box [-L/2, L/2]^D, after check_problem.
template<int D>
void set_periodic_box(sph::simulation<D>& s, const problem& problem) {
  check_problem(problem, s.physics, D);
  flecsi_lite::topology::ntree::box<D> box;
  box.lo.fill(-0.5 * problem.side);
  box.hi.fill(0.5 * problem.side);
  s.tree_settings.fixed_box = box;
  s.tree_settings.periodic.fill(true);
}

/// Fills this rank's block of the lattice (positions, ids, masses, h, u): masses and h whose SPH
/// density is rho0 (sph::density_consistent_particle). The blast energy is
/// E w_i / sum_j m_j w_j per unit mass with w_i = W(|x_i|, h) of the particle's h, so that exactly E
/// (up to rounding) is deposited, spread by the kernel. With a `glass` (initial_lattice = glass)
/// the particles are the tiled glass's, of equal mass rho0 V / N. Collective.
template<int D>
void create_lattice(sph::simulation<D>& s, const problem& problem, const glass::tiling<D>* glass = nullptr) {
  std::uint64_t total = 1;
  for (int k = 0; k < D; ++k) total *= static_cast<std::uint64_t>(problem.per_side);
  const auto block = flecsi_lite::io::block_slice(total, flecsi_lite::runtime::rank(), flecsi_lite::runtime::size());
  set_periodic_box(s, problem);
  sph::create_particles(s, block.count);
  const double spacing = problem.side / double(problem.per_side);
  // The mass and h whose SPH density sum on the cubic lattice is rho0 (not 0.2-0.4% more).
  const auto particle =
    glass ? glass->particle(s.physics, problem.rho0, spacing)
          : sph::density_consistent_particle<D>(s.physics, problem.rho0, std::pow(spacing, D), [&](double h) {
              return sph::lattice_kernel_sum<D>(s.physics.kernel, h, spacing, spacing, 0.0);
            });
  const double mass = particle.mass;
  const double smoothing = particle.h;
  const double u_background = s.physics.eos.ideal.internal_energy(problem.rho0, problem.background_pressure);
  // The kernel weights of every lattice site near the centre, summed in a fixed order (the same on
  // any number of ranks): the normalization of the deposit.
  double weight_sum = 0;
  const std::int64_t n = problem.per_side;
  const auto site = [&](std::uint64_t index) {
    if (glass) return glass->position(-0.5 * problem.side, problem.side, index);
    sph::vector<D> position;
    for (int k = 0; k < D; ++k, index /= static_cast<std::uint64_t>(n))
      position[k] = (double(index % static_cast<std::uint64_t>(n)) + 0.5) * spacing - 0.5 * problem.side;
    return position;
  };
  const auto weight = [&](const sph::vector<D>& position) {
    double r2 = 0;
    for (int k = 0; k < D; ++k) r2 += position[k] * position[k];
    return flecsph::physics::dispatch_kernel<D>(s.physics.kernel,
                                                [&](auto kernel) { return kernel.value(std::sqrt(r2), smoothing); });
  };
  for (std::uint64_t i = 0; i < total; ++i) weight_sum += weight(site(i));
  sph::initial_fields(s, [&](std::size_t i, sph::initial_particle<D>& p) {
    const std::uint64_t index = block.offset + i;
    p.x = site(index);
    p.id = index;
    p.m = mass;
    p.h = smoothing;
    p.kind = sph::particle_kind::fluid;
    p.rho = problem.rho0;
    p.u = u_background + problem.energy * weight(p.x) / (mass * weight_sum);
  });
}

/// Mean density in radial shells of width `width` around the centre: sums per shell.
inline constexpr int shell_count = 128;
struct shell_sums {
  std::array<double, shell_count> rho{}, count{};
};
struct shell_reduction {
  static shell_sums combine(shell_sums a, const shell_sums& b) {
    for (int i = 0; i < shell_count; ++i) {
      a.rho[i] += b.rho[i];
      a.count[i] += b.count[i];
    }
    return a;
  }
};

template<int D>
shell_sums radial_density(double width, sph::ro<sph::vector<D>> x, sph::ro<double> rho) {
  shell_sums sums;
  for (std::size_t a = 0; a < x.size(); ++a) {
    double r2 = 0;
    for (int k = 0; k < D; ++k) r2 += x(a)[k] * x(a)[k];
    const auto shell = static_cast<std::size_t>(std::sqrt(r2) / width);
    if (shell >= shell_count) continue;
    sums.rho[shell] += rho(a);
    sums.count[shell] += 1;
  }
  return sums;
}

struct blast_comparison {
  double shock_radius = 0;   ///< Sedov-Taylor R(t)
  double front_radius = 0;   ///< where the mean density falls to (peak + rho0) / 2 outside the peak
  double peak_radius = 0;    ///< centre of the shell of highest mean density
  double peak_density = 0;   ///< that mean density
  double analytic_peak = 0;  ///< rho0 (gamma+1)/(gamma-1)
  /// The smoothed shock's half-height point against R(t).
  double relative_error() const { return (front_radius - shock_radius) / shock_radius; }
};

/// Shock position of the simulation (the radial density peak) against the similarity solution. Collective.
template<int D>
blast_comparison compare_with_sedov_taylor(sph::simulation<D>& s, const problem& problem) {
  using f = sph::fields<D>;
  const flecsph::analytic::sedov_taylor exact(D, s.physics.eos.ideal.gamma, problem.energy, problem.rho0);
  blast_comparison result;
  result.shock_radius = exact.shock_radius(s.time);
  result.analytic_peak = exact.post_shock(s.time).rho;
  const double width = 1.5 * result.shock_radius / shell_count;
  const auto sums = flecsi_lite::reduce<radial_density<D>, shell_reduction>(width, f::position()(*s.particles),
                                                                            f::density(*s.particles))
                      .get();
  std::array<double, shell_count> mean{};
  int peak = -1;
  for (int i = 0; i < shell_count; ++i) {
    if (sums.count[i] < 1) continue;
    mean[i] = sums.rho[i] / sums.count[i];
    if (mean[i] > result.peak_density) {
      result.peak_density = mean[i];
      result.peak_radius = (i + 0.5) * width;
      peak = i;
    }
  }
  // The front: linear interpolation of the shell means where they cross the half height.
  const double half = 0.5 * (result.peak_density + problem.rho0);
  for (int i = peak; i >= 0 && i + 1 < shell_count; ++i) {
    if (sums.count[i + 1] < 1 || mean[i + 1] > half) continue;
    const double fraction = (mean[i] - half) / (mean[i] - mean[i + 1]);
    result.front_radius = (i + 0.5 + fraction) * width;
    break;
  }
  return result;
}

}  // namespace sedov
