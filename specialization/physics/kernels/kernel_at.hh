// A smoothing kernel evaluated at one h for many separations: 1/h and the normalizations are
// computed once, the shape f(q) once per pair for both W and dW/dh (the same formulas as
// physics::radial_kernel, Price 2012, JCP 231, 759, sec. 2, in the same floating-point order).
// h may be one double (a target's own) or a pack of them (its neighbours', physics/simd.hh);
// the separations a double or a pack.
#pragma once

#include "specialization/physics/kernels/radial_kernel.hh"

namespace flecsph::sph {

template<class Kernel, class T = double>
struct kernel_at {
  static constexpr int D = Kernel::dimension;
  using shape = typename Kernel::shape;

  T h;
  T inverse_h;
  T value_norm;     ///< sigma / h^D
  T h_norm;         ///< sigma / h^(D+1)
  T gradient_norm;  ///< sigma / h^(D+2)

  explicit kernel_at(T h_) : kernel_at(h_, T(1.0 / h_)) {}
  /// From h and 1/h (the force loop's neighbours: 1/h once per particle, not once per pair).
  kernel_at(T h_, T inverse_h_)
      : h(h_),
        inverse_h(inverse_h_),
        value_norm(Kernel::sigma * physics::integer_power<D>(inverse_h)),
        h_norm(Kernel::sigma * physics::integer_power<D + 1>(inverse_h)),
        gradient_norm(Kernel::sigma * physics::integer_power<D + 2>(inverse_h)) {}

  /// (1/r) dW/dr: grad_a W_ab = r_ab * gradient_factor(|r_ab|); equals Kernel::gradient_factor(r, h).
  template<class R>
  R gradient_factor(R r) const {
    return gradient_norm * shape::template derivative_over_q<D>(R(r * inverse_h));
  }

  /// The same given also 1/r, with no division: 1/q = h (1/r).
  template<class R>
  R gradient_factor(R r, R inverse_r) const {
    return gradient_norm * shape::template derivative_over_q_from<D>(R(r * inverse_h), R(h * inverse_r));
  }

  /// W(r, h) and dW/dh(r, h) from one evaluation of the shape (q f'(q), with no division).
  template<class R>
  void value_and_h_derivative(R r, R& w, R& dw_dh) const {
    const R q = r * inverse_h;
    const R f = shape::template value<D>(q);
    w = value_norm * f;
    dw_dh = -h_norm * (double(D) * f + shape::template q_derivative<D>(q));
  }
};

}  // namespace flecsph::sph
