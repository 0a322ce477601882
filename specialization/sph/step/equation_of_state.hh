// The equation-of-state task (P and the sound speed from rho and u; seed Algorithm 1, line 3); the
// velocity divergence and curl that the Balsara (1995) switch reads come from the density pass
// (density.hh, velocity_gradients.hh).
#pragma once

#include "specialization/sph/model/tasks.hh"
#include "specialization/sph/step/density.hh"

#include "specialization/physics/eos.hh"
#include "specialization/physics/pressure_energy.hh"
#include "specialization/physics/viscosity.hh"

namespace flecsph::sph {

/// P / (Omega rho^2): the pressure term of a particle in the grad-h equations of motion.
inline double pressure_over_rho2(double P, double omega, double rho) { return P / (omega * rho * rho); }

/// Pressure, sound speed and P / (Omega rho^2) of every owned particle; the Balsara factor when
/// the switch is on (from the velocity gradients of the density pass; with it off the
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
