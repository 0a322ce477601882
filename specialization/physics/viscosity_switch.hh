// The time-dependent viscosity switch of Cullen & Dehnen (2010, MNRAS 408, 669; "CD10"), one
// alpha per particle, as pure per-particle functions: the shock indicator from the time
// derivative of div v, their limiter xi against shear (eq. 18), the local target alpha_loc
// (eq. 13) and the rise / exponential decay towards it (sec. 2.4). The force pass takes
// Pi_ab = alpha_ab (beta/alpha) ... (physics/viscosity.hh) with alpha_ab = (alpha_a + alpha_b)/2.
#pragma once

#include <algorithm>
#include <cmath>

namespace flecsph::physics {

/// The keys of the switch. CD10 take alpha_min = 0 and alpha_max = 1.5-2; Phantom (Price et al.
/// 2018, PASA 35, e031, sec. 2.2.9) takes 0 and 1, which is the constant scheme's alpha here so
/// that a shock gets the viscosity it has today. The decay time is tau = H / (2 l v_sig) with H
/// the kernel's support radius (CD10 sec. 2.4); Phantom's tau = h / (sigma_decay v_sig) with
/// sigma_decay = 0.1 and H = 2h is l = 0.1.
/// How d(div v)/dt is estimated: from the accelerations of the last force evaluation,
/// d(div v)/dt = div a - tr(grad v grad v) (CD10 sec. 2.3 and Price et al. 2018 sec. 2.2.9, as Phantom),
/// or as the difference of div v between the particle's updates over the time between them (SWIFT's
/// SPHENIX, Borrow et al. 2022, sec. 2.4), which lags the shock by one step.
enum class divergence_rate_estimate { acceleration, difference };

/// The target alpha_loc: CD10's eq. 13, alpha_max H^2 A / (v_sig^2 + H^2 A) with H the support
/// radius, or Price et al. (2018) eqs. 40-43, min(10 h^2 A / c^2, alpha_max) with h the smoothing
/// length (support 2h for the cubic spline, as Phantom's).
enum class local_alpha_form { cullen_dehnen, price };

/// alpha at the start of a run: alpha_max (a shock present at t = 0 is damped from the first
/// step), or alpha_min, as Phantom starts (init_part sets alpha = 0, then alpha = max(alpha,
/// alpha_loc) after the first derivatives; Price et al. 2018, PASA 35, e031) and as SWIFT's SPHENIX
/// and ANARCHY start from 0.1 of an alpha_max of 2: a smooth flow (the Gresho vortex) is then
/// not damped by alpha_max for the several decay times it takes to fall.
enum class initial_alpha { alpha_max, alpha_min };

struct viscosity_switch_settings {
  bool enabled = false;  ///< off: the constant alpha (with the optional Balsara factor)
  double alpha_min = 0.0;
  double alpha_max = 1.0;
  double decay_length = 0.1;  ///< l of tau = H / (2 l v_sig)
  divergence_rate_estimate rate = divergence_rate_estimate::acceleration;
  local_alpha_form form = local_alpha_form::price;
  initial_alpha start = initial_alpha::alpha_max;
};

/// alpha at the start of a run (`viscosity_switch_start`): alpha_max, or alpha_min as Phantom.
inline double starting_alpha(const viscosity_switch_settings& settings) {
  return settings.start == initial_alpha::alpha_min ? settings.alpha_min : settings.alpha_max;
}

/// d(div v)/dt = div a - sum_kl (dv_k/dx_l)(dv_l/dx_k) (CD10 sec. 2.3; Price et al. 2018 sec. 2.2.9):
/// the time derivative of the velocity gradient's trace along the particle's path, from the
/// divergence of the acceleration and the gradient tensor itself, with no lag behind the flow.
template<int D>
double divergence_rate_from_acceleration(double acceleration_divergence, const double (&gradient)[D][D]) {
  double product_trace = 0;
  for (int k = 0; k < D; ++k)
    for (int l = 0; l < D; ++l) product_trace += gradient[k][l] * gradient[l][k];
  return acceleration_divergence - product_trace;
}

/// CD10's limiter xi (eq. 18): |2 (1 - R)^4 div v|^2 / (|2 (1 - R)^4 div v|^2 + tr(S S^T)),
/// S the traceless symmetric part of the velocity gradient (shear) and R = (1/rho) sum_b
/// sign(div v_b) m_b W_ab in [-1, 1] (eq. 17): R = -1 where every neighbour converges (a shock:
/// the compression term counts 16 times), R = 1 where all expand. 1 where nothing moves.
inline double cullen_dehnen_limiter(double div_v, double shear_squared, double R) {
  const double one_minus_R = 1.0 - R;
  const double squared = one_minus_R * one_minus_R;
  const double compression = 2.0 * squared * squared * div_v;
  const double compression_squared = compression * compression;
  const double total = compression_squared + shear_squared;
  return total > 0 ? compression_squared / total : 1.0;
}

/// alpha_loc = alpha_max H^2 A / (v_sig^2 + H^2 A), A = xi max(-d(div v)/dt, 0) (CD10 eq. 13):
/// approaches alpha_max only where the compression grows within a signal-crossing time of H.
inline double cullen_dehnen_local_alpha(double div_v_rate, double xi, double support_radius, double signal_velocity,
                                        double alpha_max) {
  const double A = xi * std::max(-div_v_rate, 0.0);
  const double source = support_radius * support_radius * A;
  const double total = signal_velocity * signal_velocity + source;
  return total > 0 ? alpha_max * source / total : 0.0;
}

/// alpha_loc = min(10 h^2 A / c^2, alpha_max), A = xi max(-d(div v)/dt, 0) (Price et al. 2018,
/// PASA 35, e031, eqs. 40-43; Phantom's get_alphaloc): h the smoothing length (10 h^2 = 2.5 H^2 for
/// a support H = 2h) and c the particle's sound speed, linear in the source up to alpha_max, so
/// a shock reaches alpha_max where CD10's saturating form stays near alpha_max / 2.
inline double price_local_alpha(double div_v_rate, double xi, double smoothing_length, double sound_speed,
                                double alpha_max) {
  const double A = xi * std::max(-div_v_rate, 0.0);
  const double c2 = sound_speed * sound_speed;
  if (!(c2 > 0)) return A > 0 ? alpha_max : 0.0;
  return std::min(10.0 * smoothing_length * smoothing_length * A / c2, alpha_max);
}

/// The new alpha after a step of length dt (CD10 sec. 2.4): at once alpha_loc when that is
/// larger, else alpha_loc + (alpha - alpha_loc) exp(-dt / tau), tau = H / (2 l v_sig); kept
/// within [alpha_min, alpha_max].
inline double cullen_dehnen_alpha(double alpha, double alpha_local, double dt, double support_radius,
                                  double signal_velocity, const viscosity_switch_settings& settings) {
  double next;
  if (alpha_local >= alpha) {
    next = alpha_local;
  } else if (signal_velocity > 0) {
    const double tau = support_radius / (2.0 * settings.decay_length * signal_velocity);
    next = alpha_local + (alpha - alpha_local) * std::exp(-dt / tau);
  } else {
    next = alpha;  // no signal: nothing sets a time scale, alpha stays
  }
  return std::clamp(next, settings.alpha_min, settings.alpha_max);
}

}  // namespace flecsph::physics
