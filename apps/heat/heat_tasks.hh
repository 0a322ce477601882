// Tasks of the heat-diffusion example: explicit (FTCS) finite differences for u_t = kappa u_xx
// on the periodic unit interval, and the exact solution of the initial data 1 + sin(2 pi x).
// Each task states its privileges in its parameter types; the executor does the rest.
#pragma once

#include "heat_fields.hh"

#include "flecsi_lite/execution.hh"

#include <cmath>

namespace heat {
using flecsi_lite::na;
using flecsi_lite::ro;
using flecsi_lite::rw;
using flecsi_lite::wo;

inline double exact(double x, double t, double kappa) {
  const double pi = 3.14159265358979323846;
  return 1.0 + std::exp(-4 * pi * pi * kappa * t) * std::sin(2 * pi * x);
}

inline void initialize(const mesh& m, field<double>::accessor<wo> u) {
  const double dx = 1.0 / m.global_size();
  flecsi_lite::forall(u.size(), [&](std::size_t i) { u(i) = exact((m.global_index(i) + 0.5) * dx, 0.0, 1.0); });
}

/// One explicit step; reads the neighbours' ghost values (a ghost copy precedes it when stale).
inline void diffuse(const mesh& m, field<double>::accessor<ro, ro> u, field<double>::accessor<wo> next,
                    double courant) {
  flecsi_lite::forall(next.size(), [&](std::size_t i) {
    const double left = u(m.neighbor(i, -1)), right = u(m.neighbor(i, +1));
    next(i) = u(i) + courant * (left - 2 * u(i) + right);
  });
}

inline void copy(field<double>::accessor<ro> from, field<double>::accessor<wo> to) {
  flecsi_lite::forall(to.size(), [&](std::size_t i) { to(i) = from(i); });
}

/// Largest deviation from the exact solution on this rank.
inline double max_error(const mesh& m, field<double>::accessor<ro> u, double t, double kappa) {
  const double dx = 1.0 / m.global_size();
  double worst = 0;
  for (std::size_t i = 0; i < u.size(); ++i)
    worst = std::max(worst, std::abs(u(i) - exact((m.global_index(i) + 0.5) * dx, t, kappa)));
  return worst;
}

/// Total heat on this rank, summed exactly so that the global total is rank-count independent.
inline flecsi_lite::util::exact_sum total_heat(const mesh& m, field<double>::accessor<ro> u) {
  flecsi_lite::util::exact_sum sum;
  for (std::size_t i = 0; i < u.size(); ++i) sum.add(u(i) / m.global_size());
  return sum;
}
}  // namespace heat
