// A uniform external gravitational field for the gas SPH: the force task's accelerations of the
// fluid particles get g added (walls stay fixed), and the time step's acceleration criterion,
// dt <= acceleration_factor sqrt(h / |a|), is taken again with the total acceleration (the force
// task took it without g). Placed after "forces" in the force evaluation (sph_model.hh), so that
// it acts at t = 0 and in every step; global time steps only (an inactive particle of individual
// steps keeps its acceleration, which would get g twice).
#pragma once

#include "specialization/sph.hh"

#include <cmath>
#include <limits>

namespace rayleigh_taylor {
namespace sph = flecsph::sph;

/// Adds g to the acceleration of every fluid particle; returns the smallest of `earlier` and
/// factor sqrt(h / |a|) over them.
template<int D>
double add_uniform_gravity(sph::vector<D> g, double factor, double earlier, sph::ro<sph::particle_kind> kind,
                           sph::ro<double> h, sph::rw<sph::vector<D>> acceleration) {
  double smallest = std::numeric_limits<double>::max();
  flecsi_lite::forall_reduce(
    kind.size(),
    [&](std::size_t a, double& local_smallest) {
      if (kind(a) != sph::particle_kind::fluid) return;
      double a2 = 0;
      for (int k = 0; k < D; ++k) {
        acceleration(a)[k] += g[k];
        a2 += acceleration(a)[k] * acceleration(a)[k];
      }
      if (a2 > 0) local_smallest = std::min(local_smallest, factor * std::sqrt(h(a) / std::sqrt(a2)));
    },
    Kokkos::Min<double>(smallest), "rayleigh_taylor::add_uniform_gravity");
  return std::min(smallest, earlier);
}

/// The action: g on the accelerations of the force evaluation just done, and the step's time
/// step (s.next_time_step, a global minimum) shortened where the total acceleration needs it.
template<int D>
void apply_uniform_gravity(sph::simulation<D>& s, const sph::vector<D>& g) {
  using f = sph::fields<D>;
  auto& p = *s.particles;
  const double earlier = s.next_time_step.get();
  s.next_time_step = flecsi_lite::reduce<add_uniform_gravity<D>, flecsi_lite::reduction::min>(
    g, s.physics.acceleration_factor, earlier, f::kind(p), f::smoothing_length()(p), f::acceleration(p));
}

}  // namespace rayleigh_taylor
