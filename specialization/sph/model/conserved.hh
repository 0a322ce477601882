// Conserved quantities of an SPH run: mass, linear and angular momentum, kinetic, internal,
// gravitational potential (with self-gravity) and total energy, summed exactly (Demmel & Nguyen 2015 superaccumulator, util::exact_sum) so that
// the totals are bitwise the same on any number of ranks and threads.
#pragma once

#include "specialization/sph/model/tasks.hh"

#include "flecsi_lite/util.hh"

#include <array>
#include <vector>

namespace flecsph::sph {

/// Number of angular momentum components in D dimensions: 0 (1D), 1 (L_z in 2D), 3 (3D).
template<int D>
inline constexpr int angular_components = D == 3   ? 3
                                          : D == 2 ? 1
                                                   : 0;

/// The totals as doubles. Momentum, angular momentum and energy include what the fluid gave the
/// wall particles (boundary impulse and work), so they are conserved with walls too.
template<int D>
struct conserved_totals {
  double mass = 0;
  vector<D> momentum{};
  std::array<double, angular_components<D>> angular_momentum{};
  double kinetic = 0;
  double internal = 0;
  double potential = 0;  ///< W = 1/2 sum m Phi (self-gravity; 0 without)
  double total = 0;      ///< kinetic + internal + potential (+ the walls' work), summed exactly
  double boundary = 0;   ///< the energy the walls received
};

/// The exact partial sums one rank contributes; combined over ranks by conserved_reduction.
template<int D>
struct conserved_sums {
  using exact_sum = flecsi_lite::util::exact_sum;
  exact_sum mass, kinetic, internal, potential, total, boundary;
  std::array<exact_sum, D> momentum;
  std::array<exact_sum, angular_components<D>> angular_momentum;

  conserved_sums& operator+=(const conserved_sums& other) {
    mass += other.mass;
    kinetic += other.kinetic;
    internal += other.internal;
    potential += other.potential;
    total += other.total;
    boundary += other.boundary;
    for (int k = 0; k < D; ++k) momentum[k] += other.momentum[k];
    for (int k = 0; k < angular_components<D>; ++k) angular_momentum[k] += other.angular_momentum[k];
    return *this;
  }

  conserved_totals<D> totals() const {
    conserved_totals<D> t;
    t.mass = mass.value();
    t.kinetic = kinetic.value();
    t.internal = internal.value();
    t.potential = potential.value();
    t.total = total.value();
    t.boundary = boundary.value();
    for (int k = 0; k < D; ++k) t.momentum[k] = momentum[k].value();
    for (int k = 0; k < angular_components<D>; ++k) t.angular_momentum[k] = angular_momentum[k].value();
    return t;
  }
};

/// The reduction operation of reduce<conserved_quantities<D>, conserved_reduction>: exact, so
/// the combined sums do not depend on the order or the number of ranks.
struct conserved_reduction {
  template<class Sums>
  static Sums combine(Sums a, const Sums& b) {
    return a += b;
  }
};

namespace detail {
/// L = x cross p, the components that exist in D dimensions.
template<int D>
std::array<double, angular_components<D>> cross(const vector<D>& x, const vector<D>& p) {
  if constexpr (D == 3)
    return {x[1] * p[2] - x[2] * p[1], x[2] * p[0] - x[0] * p[2], x[0] * p[1] - x[1] * p[0]};
  else if constexpr (D == 2)
    return {x[0] * p[1] - x[1] * p[0]};
  else {
    (void)x;
    (void)p;
    return {};
  }
}
}  // namespace detail

namespace detail {
/// The sums of conserved_quantities; `potential` (G Phi per particle) is null without gravity.
template<int D>
conserved_sums<D> conserved_sums_of(ro<vector<D>> x, ro<vector<D>> v, ro<double> m, ro<double> u,
                                    ro<particle_kind> kind, ro<vector<D>> impulse, ro<double> work,
                                    const double* potential) {
  // Chunks in parallel, each with its own accumulator; exact sums make the result order-free.
  const std::size_t n = x.size();
  const std::size_t threads = static_cast<std::size_t>(flecsi_lite::concurrency());
  const std::size_t chunks = std::max<std::size_t>(1, std::min<std::size_t>(n, 4 * threads));
  std::vector<conserved_sums<D>> partial(chunks);
  flecsi_lite::forall(
    chunks,
    [&](std::size_t c) {
      conserved_sums<D>& sums = partial[c];
      for (std::size_t a = n * c / chunks, end = n * (c + 1) / chunks; a < end; ++a) {
        vector<D> p;
        if (kind(a) == particle_kind::fluid) {
          double v2 = 0;
          for (int k = 0; k < D; ++k) {
            p[k] = m(a) * v(a)[k];
            v2 += v(a)[k] * v(a)[k];
          }
          const double kinetic = 0.5 * m(a) * v2, internal = m(a) * u(a);
          sums.mass.add(m(a));
          sums.kinetic.add(kinetic);
          sums.internal.add(internal);
          sums.total.add(kinetic);
          sums.total.add(internal);
        } else {
          for (int k = 0; k < D; ++k) p[k] = m(a) * impulse(a)[k];
          const double received = m(a) * work(a);
          sums.boundary.add(received);
          sums.total.add(received);
        }
        if (potential) {  // walls are gravitating sources too: every particle's half of its pairs
          const double energy = 0.5 * m(a) * potential[a];
          sums.potential.add(energy);
          sums.total.add(energy);
        }
        for (int k = 0; k < D; ++k) sums.momentum[k].add(p[k]);
        const auto angular = detail::cross<D>(x(a), p);
        for (int k = 0; k < angular_components<D>; ++k) sums.angular_momentum[k].add(angular[k]);
      }
    },
    "sph::conserved_quantities");
  for (std::size_t c = 1; c < chunks; ++c) partial[0] += partial[c];
  return partial[0];
}
}  // namespace detail

/// This rank's exact partial sums over its owned particles: fluid particles contribute m, m v,
/// x cross m v, m v^2/2 and m u; walls contribute their boundary impulse m J and work m w.
template<int D>
conserved_sums<D> conserved_quantities(ro<vector<D>> x, ro<vector<D>> v, ro<double> m, ro<double> u,
                                       ro<particle_kind> kind, ro<vector<D>> impulse, ro<double> work) {
  return detail::conserved_sums_of<D>(x, v, m, u, kind, impulse, work, nullptr);
}

/// The same with self-gravity: every particle (walls too) adds m Phi / 2 to the potential energy
/// W = 1/2 sum_i m_i Phi_i and to the total (Phi_i includes the self term m_i phi(0, h_i)).
template<int D>
conserved_sums<D> conserved_quantities_with_gravity(ro<vector<D>> x, ro<vector<D>> v, ro<double> m, ro<double> u,
                                                    ro<particle_kind> kind, ro<vector<D>> impulse, ro<double> work,
                                                    ro<double> potential) {
  return detail::conserved_sums_of<D>(x, v, m, u, kind, impulse, work, potential.data());
}

}  // namespace flecsph::sph
