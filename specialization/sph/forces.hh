// The force task: acceleration (seed eq. 1.9) and du/dt (eq. 1.8) in the pairwise-antisymmetric
// grad-h form (Price 2012, JCP 231, 759, eqs. 30-35), Monaghan & Gingold (1983) viscosity with the
// optional Balsara switch, Price (2008) artificial conductivity, and each particle's time step.
#pragma once

#include "specialization/sph/density.hh"
#include "specialization/sph/equation_of_state.hh"
#include "specialization/sph/kernel_at.hh"

#include "specialization/physics/viscosity.hh"

#include <algorithm>
#include <cmath>
#include <limits>

namespace flecsph::sph {

/// Accelerations and du/dt of every owned particle; returns the smallest time step over the owned
/// fluid particles (the largest double when there is none):
/// min(courant h_a / max_b v_sig,ab, acceleration_factor sqrt(h_a / |a_a|)).
///
/// For a pair (a, b) with r_ab = x_a - x_b, F_x = (1/r) dW/dr(r, h_x), F_ab = (F_a + F_b)/2 and the
/// pressure terms p_x = P_x / (Omega_x rho_x^2) (field pressure_term):
///   dv_a/dt = -sum_b m_b [p_a F_a + p_b F_b + Pi_ab F_ab] r_ab
///   du_a/dt =  sum_b m_b [p_a F_a + Pi_ab F_ab / 2] v_ab . r_ab
///            + sum_b m_b alpha_u v_sig^u (u_a - u_b) / rho_ab F_ab |r_ab|
/// The bracket of dv/dt is computed by the same symmetric expression for (a, b) and (b, a), so the
/// pair forces are exactly opposite: momentum is conserved to round-off, energy to the accuracy of
/// the time integration.
template<int D>
double compute_forces(const neighbourhood<D>& neighbours, physics_settings settings,
                      accessor<vector<D>, ro, ro> x, accessor<vector<D>, ro, ro> v, accessor<double, ro, ro> m,
                      accessor<double, ro, ro> h, accessor<double, ro, ro> rho, accessor<double, ro, ro> P,
                      accessor<double, ro, ro> cs, accessor<double, ro, ro> pressure_term,
                      accessor<double, ro, ro> u, accessor<double, ro, ro> balsara, accessor<particle_kind, ro> kind,
                      accessor<vector<D>, wo> acceleration, accessor<double, wo> du_dt) {
  flecsi_lite::timers::scoped timer("sph::forces");  // the executor times tasks, not reductions
  const neighbour_walk<D> walk(neighbours);
  const physics::viscosity_parameters viscosity = settings.viscosity;
  const double conductivity = settings.conductivity;
  const double support2 = physics::kernel_support * physics::kernel_support;
  double smallest = std::numeric_limits<double>::max();
  physics::dispatch_kernel<D>(settings.kernel, [&](auto kernel_type) {
    using Kernel = decltype(kernel_type);
    flecsi_lite::forall_reduce(
      neighbours.size(),
      [&](std::size_t a, double& local_smallest) {
        const vector<D> x_a = x(a), v_a = v(a);
        const double h_a = h(a), rho_a = rho(a), P_a = P(a), u_a = u(a), c_a = cs(a), term_a = pressure_term(a);
        const kernel_at<Kernel> kernel_a(h_a);
        const physics::viscosity_particle particle_a{rho_a, c_a, h_a, balsara(a)};
        vector<D> dv_dt{}, r;
        double du = 0, signal = c_a;
        for (std::size_t j = walk.begin(a), end = walk.end(a); j < end; ++j) {
          const std::size_t b = walk.neighbour(j);
          const double r2 = walk.separation(x_a, x(b), j, r);
          const double h_b = h(b), h_max = std::max(h_a, h_b);
          if (r2 >= support2 * h_max * h_max || r2 == 0) continue;
          const double distance = std::sqrt(r2);
          const double F_a = kernel_a.gradient_factor(distance);
          const double F_b = kernel_at<Kernel>(h_b).gradient_factor(distance);
          const double F_ab = 0.5 * (F_a + F_b);
          const vector<D>& v_b = v(b);
          double r_dot_v = 0;
          for (int k = 0; k < D; ++k) r_dot_v += r[k] * (v_a[k] - v_b[k]);
          const double rho_b = rho(b), c_b = cs(b);
          // Viscosity acts on approaching pairs only (Pi_ab = 0 otherwise).
          const double Pi = r_dot_v < 0 ? physics::artificial_viscosity(viscosity, r_dot_v, r2, particle_a,
                                                                        {rho_b, c_b, h_b, balsara(b)})
                                        : 0.0;
          const double bracket = (term_a * F_a + pressure_term(b) * F_b) + Pi * F_ab;
          const double m_b = m(b);
          for (int k = 0; k < D; ++k) dv_dt[k] -= m_b * bracket * r[k];
          du += m_b * (term_a * F_a + 0.5 * Pi * F_ab) * r_dot_v;
          if (conductivity > 0)
            du += m_b * physics::artificial_conductivity(conductivity, u_a, u(b), P_a, P(b), rho_a, rho_b,
                                                         F_ab * distance);
          signal = std::max(signal, r_dot_v < 0 ? physics::signal_velocity(c_a, c_b, r_dot_v, distance) : c_a + c_b);
        }
        acceleration(a) = dv_dt;
        du_dt(a) = du;
        if (kind(a) != particle_kind::fluid) return;
        double a2 = 0;
        for (int k = 0; k < D; ++k) a2 += dv_dt[k] * dv_dt[k];
        double dt = physics::courant_time_step(settings.courant, h_a, signal);
        if (a2 > 0) dt = std::min(dt, settings.acceleration_factor * std::sqrt(h_a / std::sqrt(a2)));
        local_smallest = std::min(local_smallest, dt);
      },
      Kokkos::Min<double>(smallest), "sph::compute_forces");
  });
  return smallest;
}

} // namespace flecsph::sph
