// Monopole and traceless quadrupole moments of point masses for Barnes-Hut gravity: accumulation,
// the parallel-axis shift that combines children into parents, and the field of the expansion
// (Barnes & Hut 1986; the expansion as in Hernquist 1987, ApJS 64, 715, with G = 1).
#pragma once

#include "flecsi_lite/topology/ntree/space.hh"

#include <array>
#include <cmath>
#include <cstddef>

namespace flecsi_lite::topology::ntree {

/// Traceless quadrupole Q_ij = sum_b m_b (3 d_i d_j - |d|^2 delta_ij), d = x_b - centre of mass,
/// stored as the upper triangle row by row (xx, xy, xz, yy, yz, zz in 3D). In 1D and 2D the
/// points are taken as embedded in 3D space with the 3D potential 1/r, so the same formulas hold.
template<int D>
using quadrupole = std::array<double, D * (D + 1) / 2>;

/// Position of Q_ij in the packed upper triangle.
template<int D>
constexpr int tensor_index(int i, int j) {
  if (i > j) {
    const int t = i;
    i = j;
    j = t;
  }
  return i * D - i * (i - 1) / 2 + (j - i);
}

/// Q += m (3 d d^T - |d|^2 I): the contribution of mass `m` at offset `d` from the centre.
template<int D>
inline void add_point_mass(quadrupole<D>& q, double m, const point<D>& d) {
  double d2 = 0;
  for (int k = 0; k < D; ++k) d2 += d[k] * d[k];
  for (int i = 0; i < D; ++i)
    for (int j = i; j < D; ++j)
      q[tensor_index<D>(i, j)] += m * (3 * d[i] * d[j] - (i == j ? d2 : 0.0));
}

/// Q += Q_child + m_child (3 d d^T - |d|^2 I): parallel-axis theorem for a child of mass
/// `m_child` whose centre of mass sits at offset `d` from the parent's.
template<int D>
inline void add_shifted(quadrupole<D>& q, const quadrupole<D>& child, double m_child,
                        const point<D>& d) {
  for (std::size_t k = 0; k < q.size(); ++k) q[k] += child[k];
  add_point_mass<D>(q, m_child, d);
}

/// Potential at x of mass `m` at `center` with quadrupole `q` about it:
/// phi = -m/r - (r.Q.r) / (2 r^5), r = x - center. Precondition: x != center.
template<int D>
inline double multipole_potential(double m, const point<D>& center, const quadrupole<D>& q,
                                  const point<D>& x) {
  point<D> r;
  double r2 = 0;
  for (int k = 0; k < D; ++k) {
    r[k] = x[k] - center[k];
    r2 += r[k] * r[k];
  }
  double rqr = 0;
  for (int i = 0; i < D; ++i)
    for (int j = 0; j < D; ++j) rqr += r[i] * q[tensor_index<D>(i, j)] * r[j];
  const double inverse_r = 1 / std::sqrt(r2);
  const double inverse_r2 = inverse_r * inverse_r;
  return -m * inverse_r - 0.5 * rqr * inverse_r2 * inverse_r2 * inverse_r;
}

/// Acceleration at x (minus the gradient of multipole_potential):
/// a = -m r/r^3 + Q r/r^5 - (5/2)(r.Q.r) r/r^7. Precondition: x != center.
template<int D>
inline point<D> multipole_acceleration(double m, const point<D>& center, const quadrupole<D>& q,
                                       const point<D>& x) {
  point<D> r;
  double r2 = 0;
  for (int k = 0; k < D; ++k) {
    r[k] = x[k] - center[k];
    r2 += r[k] * r[k];
  }
  point<D> qr{};
  double rqr = 0;
  for (int i = 0; i < D; ++i) {
    for (int j = 0; j < D; ++j) qr[i] += q[tensor_index<D>(i, j)] * r[j];
    rqr += r[i] * qr[i];
  }
  const double inverse_r = 1 / std::sqrt(r2);
  const double inverse_r2 = inverse_r * inverse_r;
  const double inverse_r3 = inverse_r2 * inverse_r;
  const double inverse_r5 = inverse_r3 * inverse_r2;
  point<D> a;
  for (int k = 0; k < D; ++k)
    a[k] = -m * r[k] * inverse_r3 + qr[k] * inverse_r5 - 2.5 * rqr * r[k] * inverse_r5 * inverse_r2;
  return a;
}

} // namespace flecsi_lite::topology::ntree
