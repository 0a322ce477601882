// Gravity softened consistently with the SPH kernel (Price & Monaghan 2007, MNRAS 374, 1347,
// sec. 2 and appendix A): the potential of a particle whose mass is spread as W(r, h), in 3D.
//
// For a kernel shape f(q) (W = sigma / h^3 f(r/h)) whose pieces are polynomials in q, the mass
// within r, m(q) = 4 pi sigma int_0^q f(t) t^2 dt (q = r/h, m(2) = 1), the force g = m(q) / r^2 and
// the potential phi with d phi / dr = g and phi = -1/r beyond 2h are polynomials too, found here by
// exact integration of the kernel's own pieces (no table, no interpolation). On piece k:
//   m(q)            = A_k + sum_n a_n q^(n+3),          a_n = 4 pi sigma c_n / (n + 3)
//   h phi           = -A_k / q + B_k + sum_n p_n q^(n+2), p_n = a_n / (n + 2)
//   h^2 d phi / d h = -(phi h + m / q) = -(B_k + sum_n d_n q^(n+2)),  d_n = 4 pi sigma c_n / (n + 2)
// with A_0 = 0 (finite at r = 0) and A_k, B_k fixed by continuity at the piece boundaries and
// phi(2h) = -1/(2h). Signs: phi < 0, g = d phi / dr > 0 (attraction: a_i = -m_j g r_ij / r).
//
//   using soft = physics::softened_gravity<physics::cubic_spline_shape>;
//   double phi = soft::potential(r, h), g_over_r = soft::radial(r, h), dphi_dh = soft::h_derivative(r, h);
#pragma once

#include "specialization/physics/kernels/cubic_spline.hh"
#include "specialization/physics/kernels/wendland.hh"

#include <Kokkos_Core.hpp>

#include <array>
#include <cstddef>

namespace flecsph::physics {

/// A polynomial sum_n c[n] x^n of degree below N, for the constant-expression derivations.
template<std::size_t N>
struct polynomial {
  std::array<double, N> c{};

  template<std::size_t M>
  constexpr polynomial<N + M - 1> operator*(const polynomial<M>& other) const {
    polynomial<N + M - 1> product;
    for (std::size_t i = 0; i < N; ++i)
      for (std::size_t j = 0; j < M; ++j) product.c[i + j] += c[i] * other.c[j];
    return product;
  }
};

/// p^K.
template<std::size_t K, std::size_t N>
constexpr auto polynomial_power(const polynomial<N>& p) {
  if constexpr (K == 0)
    return polynomial<1>{{1.0}};
  else
    return p * polynomial_power<K - 1>(p);
}

/// The 3D shape f(q) of a kernel as polynomial pieces in q: piece k holds on
/// [edges[k], edges[k+1]), with coefficients[k][n] the coefficient of q^n. One specialization per
/// shape, written from the same formulas as the shape's value<3>() (the tests compare them).
template<class Shape>
struct kernel_pieces;

/// The cubic spline: 1 - 3/2 q^2 + 3/4 q^3 on [0, 1), (2 - q)^3 / 4 on [1, 2).
template<>
struct kernel_pieces<cubic_spline_shape> {
  static constexpr std::size_t pieces = 2, terms = 4;
  static constexpr std::array<double, pieces + 1> edges{0.0, 1.0, 2.0};
  static constexpr std::array<std::array<double, terms>, pieces> coefficients() {
    const auto outer = polynomial_power<3>(polynomial<2>{{2.0, -1.0}});
    std::array<double, terms> outer_quarter{};
    for (std::size_t n = 0; n < terms; ++n) outer_quarter[n] = 0.25 * outer.c[n];
    const std::array<double, terms> inner{1.0, 0.0, -1.5, 0.75};
    return {inner, outer_quarter};
  }
};

namespace detail {
/// One Wendland piece on [0, 2): (1 - q/2)^Power times sum_n tail[n] (q/2)^n.
template<std::size_t Power, std::size_t TailTerms>
constexpr std::array<std::array<double, Power + TailTerms>, 1> wendland_piece(
  const std::array<double, TailTerms>& tail) {
  polynomial<TailTerms> in_q;
  double half_power = 1.0;
  for (std::size_t n = 0; n < TailTerms; ++n, half_power *= 0.5) in_q.c[n] = tail[n] * half_power;
  return {(polynomial_power<Power>(polynomial<2>{{1.0, -0.5}}) * in_q).c};
}
}  // namespace detail

/// Wendland C2 in 3D: (1 - s)^4 (1 + 4 s), s = q/2.
template<>
struct kernel_pieces<wendland_c2_shape> {
  static constexpr std::size_t pieces = 1, terms = 6;
  static constexpr std::array<double, pieces + 1> edges{0.0, 2.0};
  static constexpr auto coefficients() { return detail::wendland_piece<4>(std::array<double, 2>{1.0, 4.0}); }
};

/// Wendland C4 in 3D: (1 - s)^6 (1 + 6 s + 35/3 s^2).
template<>
struct kernel_pieces<wendland_c4_shape> {
  static constexpr std::size_t pieces = 1, terms = 9;
  static constexpr std::array<double, pieces + 1> edges{0.0, 2.0};
  static constexpr auto coefficients() {
    return detail::wendland_piece<6>(std::array<double, 3>{1.0, 6.0, 35.0 / 3.0});
  }
};

/// Wendland C6 in 3D: (1 - s)^8 (1 + 8 s + 25 s^2 + 32 s^3).
template<>
struct kernel_pieces<wendland_c6_shape> {
  static constexpr std::size_t pieces = 1, terms = 12;
  static constexpr std::array<double, pieces + 1> edges{0.0, 2.0};
  static constexpr auto coefficients() {
    return detail::wendland_piece<8>(std::array<double, 4>{1.0, 8.0, 25.0, 32.0});
  }
};

namespace detail {
/// sum_n c[n] x^n by Horner's rule.
template<std::size_t N>
KOKKOS_INLINE_FUNCTION constexpr double series(const std::array<double, N>& c, double x) {
  double sum = 0;
  for (std::size_t n = N; n-- > 0;) sum = sum * x + c[n];
  return sum;
}

/// One piece of the softening: its lower edge, A_k, B_k and the a_n, p_n, d_n of the top comment.
template<std::size_t Terms>
struct softening_piece {
  double lower = 0, mass_constant = 0, potential_constant = 0;
  std::array<double, Terms> mass{}, potential{}, h_term{};

  KOKKOS_INLINE_FUNCTION constexpr double mass_fraction(double q) const {
    return mass_constant + series(mass, q) * q * q * q;
  }
  /// h phi - B_k = -A_k / q + sum_n p_n q^(n+2).
  KOKKOS_INLINE_FUNCTION constexpr double potential_polynomial(double q) const {
    double value = series(potential, q) * q * q;
    if (mass_constant != 0) value -= mass_constant / q;
    return value;
  }
};

/// The exact integration of the kernel's pieces (a constant expression).
template<class Shape>
constexpr auto integrate_softening() {
  using pieces_of = kernel_pieces<Shape>;
  constexpr std::size_t pieces = pieces_of::pieces, terms = pieces_of::terms;
  constexpr double four_pi_sigma = 4.0 * pi * Shape::template normalization<3>();
  const auto c = pieces_of::coefficients();
  std::array<softening_piece<terms>, pieces> t{};
  for (std::size_t k = 0; k < pieces; ++k) {
    t[k].lower = pieces_of::edges[k];
    for (std::size_t n = 0; n < terms; ++n) {
      t[k].mass[n] = four_pi_sigma * c[k][n] / double(n + 3);
      t[k].potential[n] = t[k].mass[n] / double(n + 2);
      t[k].h_term[n] = four_pi_sigma * c[k][n] / double(n + 2);
    }
  }
  // m continuous at each inner edge: A_k = m_(k-1)(edge) - sum_n a_n edge^(n+3).
  for (std::size_t k = 1; k < pieces; ++k) {
    const double edge = pieces_of::edges[k];
    t[k].mass_constant = t[k - 1].mass_fraction(edge) - series(t[k].mass, edge) * edge * edge * edge;
  }
  // h phi(2) = -1/2, then phi continuous inward.
  t[pieces - 1].potential_constant = -0.5 - t[pieces - 1].potential_polynomial(kernel_support);
  for (std::size_t k = pieces - 1; k-- > 0;) {
    const double edge = pieces_of::edges[k + 1];
    t[k].potential_constant =
      t[k + 1].potential_polynomial(edge) + t[k + 1].potential_constant - t[k].potential_polynomial(edge);
  }
  return t;
}

template<class Shape>
inline constexpr auto softening_table = integrate_softening<Shape>();
}  // namespace detail

/// The softened potential, force and h-derivative of the 3D kernel of `Shape` (see the top).
template<class Shape>
struct softened_gravity {
  static constexpr std::size_t pieces = kernel_pieces<Shape>::pieces;
  using piece = detail::softening_piece<kernel_pieces<Shape>::terms>;

  /// m(q), the fraction of the kernel's mass within q = r/h (1 from q = 2 on).
  KOKKOS_INLINE_FUNCTION static double mass_fraction(double q) {
    if (q >= kernel_support) return 1.0;
    return piece_at(q).mass_fraction(q);
  }

  /// phi(r, h): -1/r from 2h on, finite (B_0 / h) at r = 0.
  KOKKOS_INLINE_FUNCTION static double potential(double r, double h) {
    const double inverse_h = 1.0 / h, q = r * inverse_h;
    if (q >= kernel_support) return -1.0 / r;
    const piece& p = piece_at(q);
    return inverse_h * (p.potential_polynomial(q) + p.potential_constant);
  }

  /// g(r, h) / r = m(q) / r^3 (the acceleration is -m_j (g / r) r_ij); finite at r = 0.
  KOKKOS_INLINE_FUNCTION static double radial(double r, double h) {
    const double inverse_h = 1.0 / h, q = r * inverse_h;
    if (q >= kernel_support) return 1.0 / (r * r * r);
    const piece& p = piece_at(q);
    double value = detail::series(p.mass, q);
    if (p.mass_constant != 0) value += p.mass_constant / (q * q * q);
    return inverse_h * inverse_h * inverse_h * value;
  }

  /// g(r, h) = d phi / dr = m(q) / r^2 (0 at r = 0).
  KOKKOS_INLINE_FUNCTION static double force(double r, double h) { return radial(r, h) * r; }

  /// d phi / d h at fixed r (0 from 2h on).
  KOKKOS_INLINE_FUNCTION static double h_derivative(double r, double h) {
    const double inverse_h = 1.0 / h, q = r * inverse_h;
    if (q >= kernel_support) return 0.0;
    const piece& p = piece_at(q);
    return -inverse_h * inverse_h * (p.potential_constant + q * q * detail::series(p.h_term, q));
  }

 private:
  KOKKOS_INLINE_FUNCTION static const piece& piece_at(double q) {
    const auto& table = detail::softening_table<Shape>;
    std::size_t k = 0;
    while (k + 1 < pieces && q >= table[k + 1].lower) ++k;
    return table[k];
  }
};

}  // namespace flecsph::physics
