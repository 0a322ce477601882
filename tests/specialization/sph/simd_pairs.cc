// The SIMD pair loops (physics/simd.hh) against the same loops on one double lane: for every
// particle of jittered, moving lattices in 1D, 2D and 3D, with each kernel, the force sums (with
// and without conductivity, the grad-h gravity term and pressure-energy) and the density sums (at h and at grown
// and shrunk h, so that the kernel's edge falls inside the lists) are bitwise equal: the striped
// sums (simd::striped_sum) add each list entry to the same stripe whatever the lane count. The velocity
// gradients of the density pass, on packs, are bitwise the plain loop over the list that their
// own task ran before them. The physics
// of the single lane is checked against direct sums in forces.cc and density.cc.
#include "sph_setup.hh"

#include "specialization/sph/step/density.hh"
#include "specialization/sph/step/forces.hh"

#include <catch2/catch.hpp>

#include <cmath>
#include <cstdint>
#include <cstring>
#include <type_traits>
#include <vector>

namespace {
using namespace sph_test;
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

template<class Kernel, bool Conductivity, bool GradHGravity, bool PressureEnergy, int D>
void compare_forces(const sph::neighbour_walk<D>& walk, std::size_t owned, const sph::detail::force_fields<D>& in,
                    comparison& result) {
  const flecsph::physics::viscosity_parameters viscosity{1.0, 2.0, 0.01};
  for (std::size_t a = 0; a < owned; ++a) {
    sph::vector<D> dv_lanes, dv_one;
    double du_lanes, du_one, signal_lanes, signal_one;
    sph::detail::force_sums<Kernel, Conductivity, GradHGravity, PressureEnergy, D, simd::pack>(
      walk, a, in, viscosity, 0.7, dv_lanes, du_lanes, signal_lanes);
    sph::detail::force_sums<Kernel, Conductivity, GradHGravity, PressureEnergy, D, double>(walk, a, in, viscosity, 0.7,
                                                                                           dv_one, du_one, signal_one);
    for (int k = 0; k < D; ++k) result.add(dv_lanes[k], dv_one[k]);
    result.add(du_lanes, du_one);
    result.add(signal_lanes, signal_one);
  }
}

template<class Kernel, int D>
void compare_density(const sph::neighbour_walk<D>& walk, std::size_t owned, const sph::vector<D>* x, const double* m,
                     const double* h, comparison& result) {
  sph::detail::gathered_pairs pairs;
  for (std::size_t a = 0; a < owned; ++a) {
    sph::detail::gather_pairs<D>(walk.row(a), a, x, m, pairs);
    for (double factor : {0.9, 1.0, 1.04}) {
      double rho_lanes, drho_lanes, rho_one, drho_one;
      sph::detail::density_sums<Kernel, sph::detail::density_pack>(pairs, factor * h[a], rho_lanes, drho_lanes);
      sph::detail::density_sums<Kernel, double>(pairs, factor * h[a], rho_one, drho_one);
      result.add(rho_lanes, rho_one);
      result.add(drho_lanes, drho_one);
    }
  }
}

/// div and the rotation sums of a's list as the gradient task's plain loop added them before the
/// packs: the reference bits.
template<class Kernel, int D>
void plain_gradient_sums(const sph::neighbour_walk<D>& walk, std::size_t a, const sph::vector<D>* x,
                         const sph::vector<D>* v, const double* m, double h_a, double& div, sph::vector<3>& rotation) {
  const sph::kernel_at<Kernel> kernel_a(h_a);
  const double reach2 = flecsph::physics::kernel_support * flecsph::physics::kernel_support * h_a * h_a;
  sph::vector<D> r;
  const sph::neighbour_row<D> row = walk.row(a);
  for (std::size_t j = 0, end = row.size(); j < end; ++j) {
    const std::size_t b = row.neighbour(j);
    const double r2 = row.separation(x[a], x[b], j, r);
    if (r2 >= reach2 || r2 == 0) continue;
    const double factor = m[b] * kernel_a.gradient_factor(std::sqrt(r2));
    sph::vector<3> dv{}, rr{};
    for (int k = 0; k < D; ++k) {
      dv[k] = v[a][k] - v[b][k];
      rr[k] = r[k];
      div += dv[k] * r[k] * factor;
    }
    rotation[0] += (dv[1] * rr[2] - dv[2] * rr[1]) * factor;
    rotation[1] += (dv[2] * rr[0] - dv[0] * rr[2]) * factor;
    rotation[2] += (dv[0] * rr[1] - dv[1] * rr[0]) * factor;
  }
}

/// The density pass's gradient sums (terms gathered with the density's pairs, computed on packs
/// and on one lane, summed in blocks of targets side by side) against the plain loop, target by
/// target: blocks of consecutive particles and of every third one (lists of other lengths side by
/// side, and a last block that is not full), at h and at grown and shrunk h.
template<class Kernel, int D>
void compare_gradients(const sph::neighbour_walk<D>& walk, std::size_t owned, const sph::detail::force_fields<D>& in,
                       comparison& result, std::size_t& nonzero) {
  constexpr std::size_t B = sph::detail::gradient_block;
  sph::detail::gathered_pairs pairs;
  sph::detail::gradient_terms packs_curl, one_lane_curl, packs_div;
  for (std::size_t stride : {1, 3})
    for (double factor : {0.9, 1.0, 1.04}) {  // the kernel's edge inside the list
      std::vector<std::size_t> targets;
      for (std::size_t a = 0; a < owned; a += stride) targets.push_back(a);
      for (std::size_t first = 0; first < targets.size(); first += B) {
        const std::size_t count = std::min(B, targets.size() - first);
        for (auto* terms : {&packs_curl, &one_lane_curl, &packs_div}) terms->start_block();
        for (std::size_t t = 0; t < count; ++t) {
          const std::size_t a = targets[first + t];
          const double h_a = factor * in.h[a];
          const double reach2 = flecsph::physics::kernel_support * flecsph::physics::kernel_support * h_a * h_a;
          const sph::kernel_at<Kernel> kernel_a(h_a);
          pairs.velocities.with_curl = true;
          sph::detail::gather_pairs<D>(walk.row(a), a, in.x, in.m, pairs, nullptr, in.v);
          const auto write = [&](auto curl, auto number, sph::detail::gradient_terms& terms) {
            sph::detail::write_gradient_terms<Kernel, D, decltype(curl)::value, decltype(number)>(
              pairs.velocities, pairs.r.data(), pairs.m.data(), pairs.count, kernel_a, reach2, t, terms);
          };
          write(std::true_type{}, sph::detail::density_pack{}, packs_curl);
          write(std::true_type{}, double{}, one_lane_curl);
          write(std::false_type{}, sph::detail::density_pack{}, packs_div);
        }
        double div[3][B];
        sph::vector<3> rotation[3][B];
        sph::detail::sum_gradient_terms<D, true>(packs_curl, div[0], rotation[0]);
        sph::detail::sum_gradient_terms<D, true>(one_lane_curl, div[1], rotation[1]);
        sph::detail::sum_gradient_terms<D, false>(packs_div, div[2], rotation[2]);
        for (std::size_t t = 0; t < count; ++t) {
          const std::size_t a = targets[first + t];
          double div_plain = 0;
          sph::vector<3> rotation_plain{};
          plain_gradient_sums<Kernel, D>(walk, a, in.x, in.v, in.m, factor * in.h[a], div_plain, rotation_plain);
          for (int variant = 0; variant < 3; ++variant) result.add(div[variant][t], div_plain);
          for (int variant = 0; variant < 2; ++variant)
            for (int k = 0; k < 3; ++k) result.add(rotation[variant][t][k], rotation_plain[k]);
          nonzero += div_plain != 0;
        }
      }
    }
}

template<int D, template<int> class Kernel>
void compare_kernel(const sph::neighbour_walk<D>& walk, std::size_t owned, sph::detail::force_fields<D> in,
                    comparison& forces, comparison& density, comparison& gradients, std::size_t& nonzero) {
  compare_gradients<Kernel<D>, D>(walk, owned, in, gradients, nonzero);
  compare_forces<Kernel<D>, false, false, false, D>(walk, owned, in, forces);
  compare_forces<Kernel<D>, true, false, false, D>(walk, owned, in, forces);
  {
    sph::detail::force_fields<D> pressure_energy = in;
    pressure_energy.gamma_minus_one = 0.4;
    pressure_energy.pressure_grad_h = in.P;  // any field: the terms' arithmetic is what is compared
    compare_forces<Kernel<D>, true, false, true, D>(walk, owned, pressure_energy, forces);
  }
  if constexpr (D == 3) {
    in.half_G = 0.35;
    in.zeta_over_omega = in.balsara;  // any field: the term's arithmetic is what is compared
    compare_forces<Kernel<D>, true, true, false, D>(walk, owned, in, forces);
  }
  compare_density<Kernel<D>, D>(walk, owned, in.x, in.m, in.h, density);
}

template<int D>
void compare_all(bool periodic) {
  using f = sph::fields<D>;
  sph::simulation<D> s;
  s.physics.balsara = true;  // Balsara factors between 0 and 1, different per particle
  s.physics.eos.ideal.gamma = 1.4;
  load_lattice(s, {D == 3 ? 9 : (D == 2 ? 20 : 60), periodic, 1.0, 1.0, 0.3, 0.8, 0.5});
  sph::update_neighbours(s);
  sph::update_density(s);
  sph::update_pressure(s);
  sph::update_forces(s);
  s.next_time_step.get();
  auto& p = *s.particles;
  const auto x = flecsi_lite::host_view(f::position()(p));
  const auto v = flecsi_lite::host_view(f::velocity(p));
  const auto m = flecsi_lite::host_view(f::mass()(p));
  const auto h = flecsi_lite::host_view(f::smoothing_length()(p));
  const auto rho = flecsi_lite::host_view(f::density(p));
  const auto P = flecsi_lite::host_view(f::pressure(p));
  const auto cs = flecsi_lite::host_view(f::sound_speed(p));
  const auto term = flecsi_lite::host_view(f::pressure_term(p));
  const auto u = flecsi_lite::host_view(f::internal_energy(p));
  const auto balsara = flecsi_lite::host_view(f::balsara(p));
  sph::detail::force_fields<D> in{x.data(), v.data(),  m.data(),    h.data(), rho.data(),
                                  P.data(), cs.data(), term.data(), u.data(), balsara.data()};
  std::vector<double> inverse_h;
  sph::detail::inverse_smoothing_lengths(h.data(), h.size(), inverse_h);
  in.inverse_h = inverse_h.data();
  const sph::neighbour_walk<D> walk(s.neighbours.host());
  const std::size_t owned = p.owned_size();
  comparison forces, density, gradients;
  std::size_t nonzero_divergences = 0;
  compare_kernel<D, flecsph::physics::cubic_spline>(walk, owned, in, forces, density, gradients, nonzero_divergences);
  compare_kernel<D, flecsph::physics::wendland_c2>(walk, owned, in, forces, density, gradients, nonzero_divergences);
  compare_kernel<D, flecsph::physics::wendland_c4>(walk, owned, in, forces, density, gradients, nonzero_divergences);
  compare_kernel<D, flecsph::physics::wendland_c6>(walk, owned, in, forces, density, gradients, nonzero_divergences);
  INFO("D = " << D << ", " << simd::lanes<simd::pack> << " lanes, " << owned << " particles");
  CHECK(forces.sums > 0);
  CHECK(density.sums > 0);
  CHECK(forces.different == 0);
  CHECK(density.different == 0);
  CHECK(nonzero_divergences > 0);  // the lattice moves: the compared sums are not all zero
  CHECK(gradients.different == 0);
}
}  // namespace

TEST_CASE("the build's pair loops run on packs of several lanes", "[sph][simd]") {
#if FLECSPH_HAVE_STD_SIMD
  CHECK(simd::lanes<simd::pack> >= 2);
#else
  WARN("no std::experimental::simd here: the pair loops run on one lane");
#endif
}

TEST_CASE("force, density and velocity gradient sums on packs are bitwise those on one lane", "[sph][simd]") {
  for (bool periodic : {true, false}) {
    compare_all<1>(periodic);
    compare_all<2>(periodic);
    compare_all<3>(periodic);
  }
}

TEST_CASE("striped sums do not depend on the lane count", "[sph][simd]") {
  // Terms of mixed signs and magnitudes, where the order of the adds shows in the bits.
  std::vector<double> terms(8 * 13);
  std::uint64_t state = 12345;
  for (double& t : terms) {  // random signs, mantissas and magnitudes 1e-8 to 1e8
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    const double mantissa = double(state >> 11) * 0x1.0p-53, sign = (state >> 10) & 1 ? 1.0 : -1.0;
    t = sign * (1 + mantissa) * std::pow(10.0, double(int(state >> 59) % 17 - 8));
  }
  const auto sum_on = [&](auto pack_type) {
    using T = decltype(pack_type);
    simd::striped_sum<T> sum;
    for (std::size_t i = 0; i < terms.size(); i += simd::lanes<T>) sum.add(simd::load<T>(terms.data() + i));
    return sum.total();
  };
  double stripe[4] = {0, 0, 0, 0};
  for (std::size_t i = 0; i < terms.size(); ++i) stripe[i % 4] += terms[i];
  const double expected = (stripe[0] + stripe[1]) + (stripe[2] + stripe[3]);
  CHECK(bits(sum_on(double{})) == bits(expected));
  CHECK(bits(sum_on(simd::pack_at_most<2>{})) == bits(expected));
  CHECK(bits(sum_on(simd::pack_at_most<4>{})) == bits(expected));
  CHECK(bits(sum_on(simd::pack{})) == bits(expected));
  double in_order = 0;
  for (double t : terms) in_order += t;
  CHECK(bits(in_order) != bits(expected));  // the terms do tell the orders apart
}
