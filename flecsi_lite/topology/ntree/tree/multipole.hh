// Monopole and traceless quadrupole moments of point masses for Barnes-Hut gravity: accumulation,
// the parallel-axis shift that combines children into parents, and the field of the expansion
// (Barnes & Hut 1986; the expansion as in Hernquist 1987, ApJS 64, 715, with G = 1).
//
// Why Eigen here: the moments are small dense tensors (a D x D matrix, and the gravity tensors
// to come), and Eigen's fixed-size types write them as the formulas read (outer products,
// matrix-vector products, trace) with no heap and no loops over packed indices. Points stay
// point<D> = std::array (the element type of fields, I/O and MPI); Eigen::Map views them here.
#pragma once

#include "flecsi_lite/topology/ntree/space.hh"

#include <Eigen/Core>

#include <cmath>

namespace flecsi_lite::topology::ntree {

/// A displacement in D dimensions as an Eigen column vector (the algebra type of this header).
template<int D>
using column_vector = Eigen::Matrix<double, D, 1>;

/// Traceless quadrupole Q_ij = sum_b m_b (3 d_i d_j - |d|^2 delta_ij), d = x_b - centre of mass:
/// a symmetric D x D matrix, stored whole (the 3 extra doubles in 3D are a few bytes per
/// particle and buy Eigen's matrix products). Every entry is rounded the same way as its mirror,
/// so the stored matrix is exactly symmetric. In 1D and 2D the points are taken as embedded in 3D
/// space with the 3D potential 1/r, so the same formulas hold: Q is then the D x D block of the
/// traceless 3D tensor, with trace (3 - D) sum_b m_b |d|^2.
template<int D>
using quadrupole = Eigen::Matrix<double, D, D>;

/// A point seen as an Eigen vector, without a copy (read-only and writable views).
template<int D>
inline Eigen::Map<const column_vector<D>> as_column_vector(const point<D>& p) {
  return Eigen::Map<const column_vector<D>>(p.data());
}
template<int D>
inline Eigen::Map<column_vector<D>> as_column_vector(point<D>& p) {
  return Eigen::Map<column_vector<D>>(p.data());
}

/// Q += m (3 d d^T - |d|^2 I): the contribution of mass `m` at offset `d` from the centre.
template<int D>
inline void add_point_mass(quadrupole<D>& q, double m, const column_vector<D>& d) {
  // d d^T evaluated on its own: d_i d_j == d_j d_i exactly, which keeps Q exactly symmetric
  // (inside a larger expression Eigen would fold the 3 into d, giving (3 d_i) d_j != (3 d_j) d_i).
  const quadrupole<D> outer = d * d.transpose();
  q += m * (3.0 * outer - d.squaredNorm() * quadrupole<D>::Identity());
}

/// Q += Q_child + m_child (3 d d^T - |d|^2 I): parallel-axis theorem for a child of mass
/// `m_child` whose centre of mass sits at offset `d` from the parent's.
template<int D>
inline void add_shifted(quadrupole<D>& q, const quadrupole<D>& child, double m_child, const column_vector<D>& d) {
  q += child;
  add_point_mass<D>(q, m_child, d);
}

/// Potential at x of mass `m` at `centre` with quadrupole `q` about it:
/// phi = -m/r - (r.Q.r) / (2 r^5), r = x - centre. Precondition: x != centre.
template<int D>
inline double multipole_potential(double m, const point<D>& centre, const quadrupole<D>& q, const point<D>& x) {
  const column_vector<D> r = as_column_vector<D>(x) - as_column_vector<D>(centre);
  const double rqr = r.dot(q * r);
  const double inverse_r = 1 / r.norm();
  const double inverse_r2 = inverse_r * inverse_r;
  return -m * inverse_r - 0.5 * rqr * inverse_r2 * inverse_r2 * inverse_r;
}

/// Acceleration at x (minus the gradient of multipole_potential):
/// a = -m r/r^3 + Q r/r^5 - (5/2)(r.Q.r) r/r^7. Precondition: x != centre.
template<int D>
inline point<D> multipole_acceleration(double m, const point<D>& centre, const quadrupole<D>& q, const point<D>& x) {
  const column_vector<D> r = as_column_vector<D>(x) - as_column_vector<D>(centre);
  const column_vector<D> qr = q * r;
  const double rqr = r.dot(qr);
  const double inverse_r = 1 / r.norm();
  const double inverse_r2 = inverse_r * inverse_r;
  const double inverse_r3 = inverse_r2 * inverse_r;
  const double inverse_r5 = inverse_r3 * inverse_r2;
  point<D> a;
  as_column_vector<D>(a) = (-m * inverse_r3 - 2.5 * rqr * inverse_r5 * inverse_r2) * r + inverse_r5 * qr;
  return a;
}

/// Both at once (the tree walk's inner loop): writes multipole_acceleration to `acceleration`
/// and returns multipole_potential, bit for bit, sharing r, 1/r and Q r. Precondition:
/// x != centre.
template<int D>
inline double multipole_field(double m, const point<D>& centre, const quadrupole<D>& q, const point<D>& x,
                              point<D>& acceleration) {
  const column_vector<D> r = as_column_vector<D>(x) - as_column_vector<D>(centre);
  const column_vector<D> qr = q * r;
  const double rqr = r.dot(qr);
  const double inverse_r = 1 / r.norm();
  const double inverse_r2 = inverse_r * inverse_r;
  const double inverse_r3 = inverse_r2 * inverse_r;
  const double inverse_r5 = inverse_r3 * inverse_r2;
  as_column_vector<D>(acceleration) = (-m * inverse_r3 - 2.5 * rqr * inverse_r5 * inverse_r2) * r + inverse_r5 * qr;
  return -m * inverse_r - 0.5 * rqr * inverse_r2 * inverse_r2 * inverse_r;
}

}  // namespace flecsi_lite::topology::ntree
