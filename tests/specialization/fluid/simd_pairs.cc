// The fluid's pair loops (fluid_forces.hh: dv/dt and drho/dt; solid_walls.hh: the walls'
// extrapolation sums) on packs against the same loops on one double lane, which is the loop as
// it was before packs: for every particle of jittered, moving 2D and 3D lattices with a band of
// wall particles, each kernel, laminar and artificial viscosity, no-slip and free-slip walls,
// continuity (with delta-SPH) and summation, the rates and sums are bitwise equal (the ordered
// sums add the terms in list order whatever the lane count). The physics: on a periodic lattice
// of fluid only, the pair forces cancel, so the total momentum rate is the body force's.
#include "../sph/sph_setup.hh"

#include "specialization/fluid/fluid_forces.hh"
#include "specialization/fluid/solid_walls.hh"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

namespace {
using namespace sph_test;
namespace fluid = flecsph::fluid;
namespace simd = flecsph::physics::simd;

std::uint64_t bits(double x) {
  std::uint64_t b;
  std::memcpy(&b, &x, sizeof b);
  return b;
}

/// Counts of the compared sums and of those that differ in any bit.
struct comparison {
  std::size_t sums = 0, different = 0;
  void add(double lanes, double one_lane) {
    ++sums;
    different += bits(lanes) != bits(one_lane);
  }
};

/// The fluid's fields on a lattice: rho within 2% of rho0, P and c from the Tait EOS, walls in a
/// band at the lower x (kind wall, with their own velocity), when `with_walls`.
template<int D>
struct fluid_lattice {
  sph::simulation<D> s;
  std::vector<sph::vector<D>> x, v, wall_velocity;
  std::vector<double> m, h, inverse_h, rho, P, cs;
  std::vector<sph::particle_kind> kind;
  std::size_t owned = 0;

  fluid_lattice(const fluid::fluid_settings& settings, bool periodic, bool with_walls) {
    using f = sph::fields<D>;
    load_lattice(s, {D == 3 ? 9 : 20, periodic, 1.0, 1.0, 0.3, 0.5, 0.0});
    sph::update_neighbours(s);
    auto& p = *s.particles;
    const auto xs = flecsi_lite::host_view(f::position()(p));
    const auto vs = flecsi_lite::host_view(f::velocity(p));
    const auto ms = flecsi_lite::host_view(f::mass()(p));
    const auto hs = flecsi_lite::host_view(f::smoothing_length()(p));
    const std::size_t n = xs.size();
    owned = p.owned_size();
    x.assign(xs.data(), xs.data() + n);
    v.assign(vs.data(), vs.data() + n);
    m.assign(ms.data(), ms.data() + n);
    h.resize(n);
    inverse_h.resize(n);
    rho.resize(n);
    P.resize(n);
    cs.resize(n);
    kind.resize(n);
    wall_velocity.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      h[i] = hs(i) * (1.0 + 0.1 * hashed_unit(i, 31));  // unequal h: F(h_a) != F(h_b)
      inverse_h[i] = 1.0 / h[i];
      rho[i] = settings.eos.reference_density * (1.0 + 0.02 * hashed_unit(i, 32));
      P[i] = settings.eos.pressure(rho[i]);
      cs[i] = settings.eos.sound_speed(rho[i]);
      kind[i] = with_walls && x[i][0] < 0.2 ? sph::particle_kind::wall : sph::particle_kind::fluid;
      for (int k = 0; k < D; ++k) wall_velocity[i][k] = 0.1 * hashed_unit(i, 41 + k);
    }
  }
  fluid::detail::rate_fields<D> rate_fields() const {
    return {x.data(), v.data(),  wall_velocity.data(), m.data(), h.data(), inverse_h.data(), rho.data(),
            P.data(), cs.data(), kind.data()};
  }
  fluid::detail::wall_fields<D> wall_fields() const { return {x.data(), v.data(), P.data(), rho.data(), kind.data()}; }
};

fluid::fluid_settings settings_of(fluid::viscosity_model viscosity, fluid::wall_condition walls, int D) {
  fluid::fluid_settings settings;
  settings.eos.reference_density = 1000;
  settings.eos.reference_sound_speed = 20;
  settings.viscosity = viscosity;
  settings.dynamic_viscosity = 0.5;
  settings.artificial_alpha = 0.1;
  settings.walls = walls;
  settings.delta = 0.1;
  settings.body_force[D - 1] = -9.81;
  return settings;
}

template<int D, template<int> class Kernel>
void compare_kernel(const fluid_lattice<D>& lattice, const fluid::fluid_settings& settings, comparison& rates,
                    comparison& walls) {
  using K = Kernel<D>;
  const sph::neighbour_walk<D> walk(lattice.s.neighbours.host());
  const auto in = lattice.rate_fields();
  const auto wall_in = lattice.wall_fields();
  for (bool summation : {false, true})
    for (std::size_t a = 0; a < lattice.owned; ++a) {
      sph::vector<D> dv_lanes, dv_one;
      double drho_lanes, drho_one;
      fluid::detail::fluid_rates<K, D, simd::pack>(walk, a, in, settings, summation, dv_lanes, drho_lanes);
      fluid::detail::fluid_rates<K, D, double>(walk, a, in, settings, summation, dv_one, drho_one);
      for (int k = 0; k < D; ++k) rates.add(dv_lanes[k], dv_one[k]);
      rates.add(drho_lanes, drho_one);
    }
  for (std::size_t a = 0; a < lattice.owned; ++a) {
    if (lattice.kind[a] != sph::particle_kind::wall) continue;
    const auto lanes = fluid::detail::wall_sums_of<K, D, simd::pack>(walk, a, lattice.h[a], wall_in, settings);
    const auto one = fluid::detail::wall_sums_of<K, D, double>(walk, a, lattice.h[a], wall_in, settings);
    walls.add(lanes.weight, one.weight);
    walls.add(lanes.pressure, one.pressure);
    walls.add(lanes.force_term, one.force_term);
    for (int k = 0; k < D; ++k) walls.add(lanes.velocity[k], one.velocity[k]);
  }
}

template<int D>
void compare_all(bool periodic) {
  for (auto viscosity : {fluid::viscosity_model::laminar, fluid::viscosity_model::artificial})
    for (auto walls : {fluid::wall_condition::no_slip, fluid::wall_condition::free_slip}) {
      const auto settings = settings_of(viscosity, walls, D);
      const fluid_lattice<D> lattice(settings, periodic, true);
      comparison rates, wall_sums;
      compare_kernel<D, flecsph::physics::cubic_spline>(lattice, settings, rates, wall_sums);
      compare_kernel<D, flecsph::physics::wendland_c2>(lattice, settings, rates, wall_sums);
      compare_kernel<D, flecsph::physics::wendland_c4>(lattice, settings, rates, wall_sums);
      INFO("D = " << D << ", " << simd::lanes<simd::pack> << " lanes, periodic " << periodic << ", laminar "
                  << (viscosity == fluid::viscosity_model::laminar) << ", no-slip "
                  << (walls == fluid::wall_condition::no_slip));
      CHECK(rates.sums > 0);
      CHECK(wall_sums.sums > 0);
      CHECK(rates.different == 0);
      CHECK(wall_sums.different == 0);
    }
}

/// sum_a m_a (dv_a/dt - g) over a periodic lattice of fluid only, against sum_a m_a |dv_a/dt - g|.
template<int D>
void check_momentum(fluid::viscosity_model viscosity) {
  const auto settings = settings_of(viscosity, fluid::wall_condition::no_slip, D);
  const fluid_lattice<D> lattice(settings, true, false);
  const sph::neighbour_walk<D> walk(lattice.s.neighbours.host());
  const auto in = lattice.rate_fields();
  sph::vector<D> total{};
  double scale = 0;
  for (std::size_t a = 0; a < lattice.owned; ++a) {
    sph::vector<D> dv;
    double drho;
    fluid::detail::fluid_rates<flecsph::physics::wendland_c2<D>, D>(walk, a, in, settings, false, dv, drho);
    for (int k = 0; k < D; ++k) {
      const double pair_part = dv[k] - settings.body_force[k];
      total[k] += lattice.m[a] * pair_part;
      scale += lattice.m[a] * std::fabs(pair_part);
    }
  }
  INFO("D = " << D << ", scale " << scale);
  CHECK(scale > 0);
  for (int k = 0; k < D; ++k) CHECK(std::fabs(total[k]) < 1e-12 * scale);
}
}  // namespace

TEST_CASE("fluid rates and wall sums on packs are bitwise those on one lane", "[fluid][simd]") {
  for (bool periodic : {true, false}) {
    compare_all<2>(periodic);
    compare_all<3>(periodic);
  }
}

TEST_CASE("the fluid's pair forces conserve momentum", "[fluid]") {
  check_momentum<2>(fluid::viscosity_model::artificial);
  check_momentum<2>(fluid::viscosity_model::laminar);
  check_momentum<3>(fluid::viscosity_model::artificial);
}
