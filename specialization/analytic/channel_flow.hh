// Transient laminar channel flows started from rest between walls at y = 0 and y = L, as series:
// plane Poiseuille flow driven by a body force F (Morris, Fox & Zhu 1997, JCP 136, 214, eq. 21)
// and Couette flow under a lid moving at v0 (the same separation of variables).
#pragma once

#include <cmath>

namespace flecsph::analytic {

/// v_x(y, t) = F/(2 nu) y (L - y) - sum_n 4 F L^2 / (nu pi^3 (2n+1)^3) sin((2n+1) pi y / L)
///             exp(-(2n+1)^2 pi^2 nu t / L^2); steady maximum F L^2 / (8 nu).
inline double poiseuille_velocity(double y, double t, double L, double F, double nu, int terms = 200) {
  const double pi = 3.14159265358979323846;
  double v = F / (2 * nu) * y * (L - y);
  for (int n = 0; n < terms; ++n) {
    const double k = 2 * n + 1;
    v -= 4 * F * L * L / (nu * pi * pi * pi * k * k * k) * std::sin(k * pi * y / L) *
         std::exp(-k * k * pi * pi * nu * t / (L * L));
  }
  return v;
}

/// v_x(y, t) = v0 y / L + sum_n 2 v0 (-1)^n / (n pi) sin(n pi y / L) exp(-n^2 pi^2 nu t / L^2).
inline double couette_velocity(double y, double t, double L, double v0, double nu, int terms = 400) {
  const double pi = 3.14159265358979323846;
  double v = v0 * y / L;
  for (int n = 1; n <= terms; ++n) {
    const double decay = std::exp(-double(n) * n * pi * pi * nu * t / (L * L));
    if (decay < 1e-300) break;
    v += 2 * v0 * (n % 2 ? -1.0 : 1.0) / (n * pi) * std::sin(n * pi * y / L) * decay;
  }
  return v;
}

}  // namespace flecsph::analytic
