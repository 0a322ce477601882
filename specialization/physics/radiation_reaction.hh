// Gravitational radiation reaction on a binary of two point masses in the quadrupole approximation:
// the 2.5 post-Newtonian term of the two-body equations of motion in harmonic coordinates
// (Damour & Deruelle 1981; Kidder 1995, Phys. Rev. D 52, 821, the 2.5PN part of the relative
// acceleration), the instantaneous quadrupole luminosity of the pair (Peters & Mathews 1963,
// Phys. Rev. 131, 435) and the circular inspiral of Peters (1964, Phys. Rev. 136, B1224).
//
// Vocabulary: x = X1 - X2 is the separation vector of the two centres of mass, v = V1 - V2 their
// relative velocity, M = m1 + m2, mu = m1 m2 / M. The relative acceleration a_rr is split so that
// momentum is conserved: star 1 takes (m2 / M) a_rr, star 2 -(m1 / M) a_rr. The pair then loses
// energy at the rate mu v.a_rr; on a circular orbit this is exactly Peters' (32/5) G^4 m1^2 m2^2 M /
// (c^5 a^5), and the angular momentum mu |x x a_rr| exactly his (32/5) G^(7/2) m1^2 m2^2 sqrt(M) /
// (c^5 a^(7/2)) (unit test unit.physics.radiation_reaction).
#pragma once

#include <array>
#include <cmath>

namespace flecsph::physics {

using vector3 = std::array<double, 3>;

/// The 2.5PN relative acceleration (harmonic gauge):
///   a_rr = (8/5) G^2 M mu / (c^5 r^3) [ rdot n (18 v^2 + (2/3) G M / r - 25 rdot^2)
///                                       - v (6 v^2 - 2 G M / r - 15 rdot^2) ],
/// n = x / r, rdot = n.v. On a circular orbit (rdot = 0, v^2 = G M / r) it is the drag
/// -(32/5) G^3 M^2 mu v / (c^5 r^4).
inline vector3 radiation_reaction_acceleration(const vector3& x, const vector3& v, double G, double m1, double m2,
                                               double c) {
  const double M = m1 + m2, mu = m1 * m2 / M;
  const double r = std::sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
  if (!(r > 0)) return {0, 0, 0};
  vector3 n;
  for (int k = 0; k < 3; ++k) n[k] = x[k] / r;
  const double rdot = n[0] * v[0] + n[1] * v[1] + n[2] * v[2];
  const double v2 = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
  const double potential = G * M / r;  // G M / r
  const double c5 = c * c * c * c * c;
  const double scale = 1.6 * G * G * M * mu / (c5 * r * r * r);
  const double along_n = rdot * (18 * v2 + (2.0 / 3.0) * potential - 25 * rdot * rdot);
  const double along_v = 6 * v2 - 2 * potential - 15 * rdot * rdot;
  return {scale * (along_n * n[0] - along_v * v[0]), scale * (along_n * n[1] - along_v * v[1]),
          scale * (along_n * n[2] - along_v * v[2])};
}

/// The quadrupole-formula luminosity of two point masses on any Keplerian orbit (Peters & Mathews
/// 1963): L = (8/15) G^3 M^2 mu^2 / (c^5 r^4) (12 v^2 - 11 rdot^2); (32/5) G^4 mu^2 M^3 / (c^5 r^5)
/// on a circle.
inline double quadrupole_luminosity(const vector3& x, const vector3& v, double G, double m1, double m2, double c) {
  const double M = m1 + m2, mu = m1 * m2 / M;
  const double r2 = x[0] * x[0] + x[1] * x[1] + x[2] * x[2];
  if (!(r2 > 0)) return 0;
  const double r = std::sqrt(r2);
  const double rdot = (x[0] * v[0] + x[1] * v[1] + x[2] * v[2]) / r;
  const double v2 = v[0] * v[0] + v[1] * v[1] + v[2] * v[2];
  const double c5 = c * c * c * c * c;
  return 8.0 / 15.0 * G * G * G * M * M * mu * mu / (c5 * r2 * r2) * (12 * v2 - 11 * rdot * rdot);
}

/// Peters (1964): a circular orbit shrinks as a(t)^4 = a0^4 - (256/5) G^3 m1 m2 M t / c^5; the
/// rate constant beta = (64/5) G^3 m1 m2 M / c^5 (so a^4 = a0^4 - 4 beta t).
inline double peters_rate(double G, double m1, double m2, double c) {
  const double c5 = c * c * c * c * c;
  return 12.8 * G * G * G * m1 * m2 * (m1 + m2) / c5;
}

/// a(t) from a0 (0 once the point masses would have met).
inline double peters_separation(double a0, double t, double G, double m1, double m2, double c) {
  const double fourth = a0 * a0 * a0 * a0 - 4 * peters_rate(G, m1, m2, c) * t;
  return fourth > 0 ? std::sqrt(std::sqrt(fourth)) : 0.0;
}

/// The time for the separation to fall from a0 to a1 < a0: (a0^4 - a1^4) / (4 beta).
inline double peters_time(double a0, double a1, double G, double m1, double m2, double c) {
  return (a0 * a0 * a0 * a0 - a1 * a1 * a1 * a1) / (4 * peters_rate(G, m1, m2, c));
}

}  // namespace flecsph::physics
