// The equation-of-state task (P and the sound speed from rho and u; seed Algorithm 1, line 3) and
// the velocity divergence and curl that the Balsara (1995) switch needs (Price 2012, eqs. 100-101).
#pragma once

#include "specialization/sph/model/tasks.hh"
#include "specialization/sph/step/density.hh"

#include "specialization/physics/eos.hh"
#include "specialization/physics/pressure_energy.hh"
#include "specialization/physics/viscosity.hh"

namespace flecsph::sph {

/// div v_a = -1/(Omega_a rho_a) sum_b m_b v_ab . grad_a W_ab(h_a) and |curl v_a| (the cross
/// product form; zero in 1D) of the owned targets of one part (neighbourhood::targets): the
/// interior ones with Ghost = na, the boundary ones with Ghost = ro.
template<int D, flecsi_lite::privilege Ghost>
void compute_velocity_gradients(neighbours_ro<D> neighbours_object, physics_settings settings,
                                ro_neighbours<vector<D>, Ghost> x, ro_neighbours<vector<D>, Ghost> v,
                                ro_neighbours<double, Ghost> m, ro<double> h, ro<double> rho, ro<double> omega,
                                wo<double> divergence, wo<double> curl) {
  const neighbourhood<D>& neighbours = *neighbours_object;
  const neighbour_walk<D> walk(neighbours);
  const std::vector<std::uint32_t>& targets = neighbours.targets(Ghost);
  const bool with_curl = curl.data() != nullptr;  // absent without the Balsara switch: div v only
  physics::dispatch_kernel<D>(settings.kernel, [&](auto kernel) {
    using Kernel = decltype(kernel);
    flecsi_lite::forall(
      targets.size(),
      [&](std::size_t i) {
        const std::size_t a = targets[i];
        const double h_a = h(a);
        const kernel_at<Kernel> kernel_a(h_a);  // 1/h and the normalisation once per target
        const double reach2 = physics::kernel_support * physics::kernel_support * h_a * h_a;
        double div = 0;
        vector<3> rotation{};
        vector<D> r;
        for (std::size_t j = walk.begin(a), end = walk.end(a); j < end; ++j) {
          const std::size_t b = walk.neighbour(j);
          const double r2 = walk.separation(x(a), x(b), j, r);
          if (r2 >= reach2 || r2 == 0) continue;
          const double factor = m(b) * kernel_a.gradient_factor(std::sqrt(r2));  // grad W = r factor
          vector<3> dv{}, rr{};
          for (int k = 0; k < D; ++k) {
            dv[k] = v(a)[k] - v(b)[k];
            rr[k] = r[k];
            div += dv[k] * r[k] * factor;
          }
          rotation[0] += (dv[1] * rr[2] - dv[2] * rr[1]) * factor;
          rotation[1] += (dv[2] * rr[0] - dv[0] * rr[2]) * factor;
          rotation[2] += (dv[0] * rr[1] - dv[1] * rr[0]) * factor;
        }
        const double scale = -1.0 / (omega(a) * rho(a));
        divergence(a) = scale * div;
        if (with_curl)
          curl(a) = std::fabs(scale) *
                    std::sqrt(rotation[0] * rotation[0] + rotation[1] * rotation[1] + rotation[2] * rotation[2]);
      },
      "sph::compute_velocity_gradients");
  });
}

/// P / (Omega rho^2): the pressure term of a particle in the grad-h equations of motion.
inline double pressure_over_rho2(double P, double omega, double rho) { return P / (omega * rho * rho); }

/// Pressure, sound speed and P / (Omega rho^2) of every owned particle; the Balsara factor when
/// the switch is on (from the velocity gradients of compute_velocity_gradients; with it off the
/// gradients and the factor are absent fields, empty accessors, and the force loop takes 1).
/// Pressure-energy (P_bar present): P = P_bar of the density pass, c = sqrt(gamma P_bar / rho)
/// and the pressure term A = (gamma-1) u / P_bar (physics/pressure_energy.hh).
template<int D>
void compute_equation_of_state(physics_settings settings, ro<double> rho, ro<double> u, ro<double> h, ro<double> omega,
                               ro<double> divergence, ro<double> curl, ro<double> P_bar, wo<double> pressure,
                               wo<double> sound_speed, wo<double> pressure_term, wo<double> balsara) {
  const physics::equation_of_state eos = settings.eos;
  const bool with_balsara = settings.balsara && balsara.data() != nullptr;
  const bool smoothed = P_bar.data() != nullptr;
  const double gamma = eos.ideal.gamma;
  flecsi_lite::forall(
    rho.size(),
    [&](std::size_t a) {
      if (smoothed) {
        pressure(a) = P_bar(a);
        pressure_term(a) = physics::pressure_energy_term(gamma - 1.0, u(a), P_bar(a));
        sound_speed(a) = physics::pressure_energy_sound_speed(gamma, P_bar(a), rho(a));
      } else {
        pressure(a) = eos.pressure(rho(a), u(a));
        pressure_term(a) = pressure_over_rho2(pressure(a), omega(a), rho(a));
        sound_speed(a) = eos.sound_speed(rho(a), u(a));
      }
      if (with_balsara) balsara(a) = physics::balsara_switch(divergence(a), curl(a), sound_speed(a), h(a));
    },
    "sph::compute_equation_of_state");
}

}  // namespace flecsph::sph
