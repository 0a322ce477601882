// Sedov-Taylor similarity solution for a uniform medium (omega = 0) after Kamm & Timmes (2007),
// "On efficient generation of numerically robust Sedov solutions", LA-UR-07-2849, eqs. 13-56.
#include "specialization/analytic/sedov_taylor.hh"

#include "specialization/analytic/quadrature.hh"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace flecsph::analytic {

// The solution is parametric in V = v t / r, which runs from V0 at the centre to V2 behind the
// shock. lambda = r/R vanishes like (V - V0)^p with p = -alpha2 in (0, 1), so dlambda/dV is
// singular at the centre. We use s with V = V0 + (V2 - V0) s^(1/p) instead: lambda is then
// linear in s near s = 0, the energy integrand is smooth, and root finding is well conditioned.

namespace {
constexpr double pi = 3.14159265358979323846;
}

sedov_taylor::sedov_taylor(int dimension, double gamma, double energy, double rho0)
    : dimension_(dimension), gamma_(gamma), energy_(energy), rho0_(rho0) {
  if (dimension < 1 || dimension > 3)
    throw std::invalid_argument("Sedov-Taylor: dimension must be 1, 2 or 3, not " + std::to_string(dimension));
  if (!(gamma > 1.0) || !std::isfinite(gamma)) throw std::invalid_argument("Sedov-Taylor: gamma must be > 1");
  if (dimension == 3 && !(gamma < 7.0))
    throw std::invalid_argument(
      "Sedov-Taylor: gamma must be < 7 in 3D (gamma >= 7 gives the "
      "singular and vacuum families, which are not implemented)");
  if (!(energy > 0.0) || !std::isfinite(energy)) throw std::invalid_argument("Sedov-Taylor: energy must be > 0");
  if (!(rho0 > 0.0) || !std::isfinite(rho0)) throw std::invalid_argument("Sedov-Taylor: rho0 must be > 0");

  const double j = dimension, g = gamma;
  // Within 1e-7 of gamma = 2 the regular exponents alpha4, alpha5 ~ 2/(2-gamma) lose accuracy;
  // the special forms there are accurate to O(|gamma - 2|).
  omega3_singular_ = std::fabs(g - 2.0) < 1e-7;

  a_ = (j + 2.0) * (g + 1.0) / 4.0;  // eqs. 33-37
  b_ = (g + 1.0) / (g - 1.0);
  c_ = (j + 2.0) * g / 2.0;
  d_ = (j + 2.0) * (g + 1.0) / ((j + 2.0) * (g + 1.0) - 2.0 * (2.0 + j * (g - 1.0)));
  e_ = (2.0 + j * (g - 1.0)) / 2.0;

  const double omega2_term = 2.0 * (g - 1.0) + j;  // gamma (omega2 - omega), eqs. 42-47
  alpha0_ = 2.0 / (j + 2.0);
  alpha2_ = -(g - 1.0) / omega2_term;
  alpha1_ = (j + 2.0) * g / (2.0 + j * (g - 1.0)) * (2.0 * j * (2.0 - g) / (g * (j + 2.0) * (j + 2.0)) - alpha2_);
  alpha3_ = j / omega2_term;
  alpha4_ = omega3_singular_ ? 0.0 : alpha1_ * (j + 2.0) / (2.0 - g);
  alpha5_ = omega3_singular_ ? 0.0 : -2.0 / (2.0 - g);

  v0_ = 2.0 / ((j + 2.0) * g);          // eq. 23
  v2_ = 4.0 / ((j + 2.0) * (g + 1.0));  // eq. 17

  // Energy integral: E = A_D R^D int_0^R [rho v^2/2 + P/(gamma-1)] (r/R)^(D-1) dr/R with
  // A_D = 2, 2 pi, 4 pi. With rho2 v2^2/2 = P2/(gamma-1) this is
  // alpha = A_D 8 I / ((gamma^2 - 1)(D+2)^2),  I = int_0^1 (g f^2 + h) lambda^(D-1) dlambda.
  const gauss_legendre_rule rule(20);
  auto integrand = [&](double s) {
    const point p = evaluate(s);
    return (p.values.g * p.values.f * p.values.f + p.values.h) * std::pow(p.lambda, dimension_ - 1) * p.dlambda_ds;
  };
  double integral = integrate(integrand, 0.0, 1.0, 4, rule);
  for (int panels = 8; panels <= 4096; panels *= 2) {
    const double refined = integrate(integrand, 0.0, 1.0, panels, rule);
    const bool converged = std::fabs(refined - integral) <= 1e-13 * std::fabs(refined);
    integral = refined;
    if (converged) break;
  }
  const double area = dimension == 1 ? 2.0 : (dimension == 2 ? 2.0 * pi : 4.0 * pi);
  alpha_ = area * 8.0 * integral / ((g * g - 1.0) * (j + 2.0) * (j + 2.0));
  xi0_ = std::pow(alpha_, -1.0 / (j + 2.0));
}

sedov_taylor::point sedov_taylor::evaluate(double s) const {
  const double j = dimension_, g = gamma_;
  const double p = -alpha2_;
  const double s_power = std::pow(s, 1.0 / p);
  const double V = v0_ + (v2_ - v0_) * s_power;
  const double x1 = a_ * V;
  const double x2 = b_ * c_ * (v2_ - v0_) * s_power;  // b (c V - 1) without cancellation
  const double x3 = d_ * (1.0 - e_ * V);
  const double x4 = b_ * (1.0 - c_ * V / g);

  // Products of powers as exponentials of sums of logarithms: near gamma = 2 the exponents
  // alpha4 and alpha5 are large and of opposite sign, and separate powers would overflow.
  const double log_x1 = std::log(x1), log_x2 = std::log(x2);
  const double log_x3 = std::log(x3), log_x4 = std::log(x4);
  point result{};
  result.lambda = std::exp(-alpha0_ * log_x1 - alpha2_ * log_x2 - alpha1_ * log_x3);
  result.values.f = x1 * result.lambda;
  if (omega3_singular_) {  // Kamm & Timmes, omega = omega3 forms (x3 = x4 at gamma = 2)
    const double exponent = -j * g * (g + 1.0) * (1.0 - x1) / (2.0 * e_ * ((g + 1.0) / 2.0 - x1));
    result.values.g = std::exp(alpha3_ * log_x2 + (1.0 - 2.0 / e_) * log_x4 + exponent);
    result.values.h = std::exp(alpha0_ * j * log_x1 + (j * (g - 1.0) - g) / e_ * log_x4 + exponent);
  } else {
    result.values.g = std::exp(alpha3_ * log_x2 + alpha4_ * log_x3 + alpha5_ * log_x4);
    result.values.h = std::exp(alpha0_ * j * log_x1 + (alpha4_ - 2.0 * alpha1_) * log_x3 + (1.0 + alpha5_) * log_x4);
  }
  if (s > 0.0) {
    // d ln(lambda)/ds: the x2 factor contributes exactly 1/s; x1 and x3 through dV/ds.
    const double dV_ds = (v2_ - v0_) / p * s_power / s;
    result.dlambda_ds = result.lambda * ((-alpha0_ / V + alpha1_ * e_ / (1.0 - e_ * V)) * dV_ds + 1.0 / s);
  }
  return result;
}

double sedov_taylor::parameter_of(double lambda) const {
  // lambda(s) increases from 0 to 1; bisection to the resolution of double.
  double low = 0.0, high = 1.0;
  for (int iteration = 0; iteration < 200 && high - low > 1e-17; ++iteration) {
    const double middle = 0.5 * (low + high);
    if (middle == low || middle == high) break;
    (evaluate(middle).lambda < lambda ? low : high) = middle;
  }
  return 0.5 * (low + high);
}

sedov_similarity sedov_taylor::similarity(double lambda) const {
  if (!(lambda >= 0.0 && lambda <= 1.0)) throw std::invalid_argument("Sedov-Taylor: lambda = r/R must lie in [0, 1]");
  if (lambda == 1.0) return {1.0, 1.0, 1.0};
  return evaluate(lambda == 0.0 ? 0.0 : parameter_of(lambda)).values;
}

double sedov_taylor::shock_radius(double t) const {
  if (!(t > 0.0)) throw std::invalid_argument("Sedov-Taylor: time must be > 0");
  return xi0_ * std::pow(energy_ * t * t / rho0_, 1.0 / (dimension_ + 2.0));
}

double sedov_taylor::shock_velocity(double t) const { return 2.0 * shock_radius(t) / ((dimension_ + 2.0) * t); }

sedov_state sedov_taylor::post_shock(double t) const {
  const double U = shock_velocity(t);
  return {rho0_ * (gamma_ + 1.0) / (gamma_ - 1.0), 2.0 * U / (gamma_ + 1.0), 2.0 * rho0_ * U * U / (gamma_ + 1.0)};
}

sedov_state sedov_taylor::at(double r, double t) const {
  if (!(r >= 0.0)) throw std::invalid_argument("Sedov-Taylor: radius must be >= 0");
  const double R = shock_radius(t);
  if (r > R) return {rho0_, 0.0, 0.0};
  const sedov_state behind = post_shock(t);
  const sedov_similarity values = similarity(r / R);
  return {behind.rho * values.g, behind.v * values.f, behind.P * values.h};
}

double sedov_taylor::specific_internal_energy(const sedov_state& state) const {
  if (state.rho == 0.0) return state.P == 0.0 ? 0.0 : std::numeric_limits<double>::infinity();
  return state.P / ((gamma_ - 1.0) * state.rho);
}

}  // namespace flecsph::analytic
