// A smoothing kernel evaluated at one h for many separations: 1/h and the normalizations are
// computed once, the shape f(q) once per pair for both W and dW/dh (the same formulas as
// physics::radial_kernel, Price 2012, JCP 231, 759, sec. 2, in the same floating-point order).
#pragma once

#include "specialization/physics/kernels/radial_kernel.hh"

namespace flecsph::sph {

template<class Kernel>
struct kernel_at {
  static constexpr int D = Kernel::dimension;
  using shape = typename Kernel::shape;

  double inverse_h;
  double value_norm;     ///< sigma / h^D
  double h_norm;         ///< sigma / h^(D+1)
  double gradient_norm;  ///< sigma / h^(D+2)

  explicit kernel_at(double h)
    : inverse_h(1.0 / h), value_norm(Kernel::sigma * physics::integer_power<D>(inverse_h)),
      h_norm(Kernel::sigma * physics::integer_power<D + 1>(inverse_h)),
      gradient_norm(Kernel::sigma * physics::integer_power<D + 2>(inverse_h)) {}

  /// (1/r) dW/dr: grad_a W_ab = r_ab * gradient_factor(|r_ab|); equals Kernel::gradient_factor(r, h).
  double gradient_factor(double r) const {
    return gradient_norm * shape::template derivative_over_q<D>(r * inverse_h);
  }

  /// W(r, h) and dW/dh(r, h) from one evaluation of the shape (q f'(q), with no division).
  void value_and_h_derivative(double r, double& w, double& dw_dh) const {
    const double q = r * inverse_h;
    const double f = shape::template value<D>(q);
    w = value_norm * f;
    dw_dh = -h_norm * (D * f + shape::template q_derivative<D>(q));
  }
};

} // namespace flecsph::sph
