// Exact Riemann solver for the ideal gas (Toro, 3rd ed., ch. 4): pressure functions (4.6)-(4.8),
// Newton iteration for p* (sec. 4.3), star densities, sampling (sec. 4.5), vacuum (sec. 4.6).
#include "specialization/analytic/riemann_exact.hh"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace flecsph::analytic {

namespace {

/// Toro's gamma-dependent constants G1..G7 (sec. 4.9).
struct gamma_constants {
  explicit gamma_constants(double gamma)
      : g1((gamma - 1.0) / (2.0 * gamma)),
        g2((gamma + 1.0) / (2.0 * gamma)),
        g3(2.0 * gamma / (gamma - 1.0)),
        g4(2.0 / (gamma - 1.0)),
        g5(2.0 / (gamma + 1.0)),
        g6((gamma - 1.0) / (gamma + 1.0)),
        g7((gamma - 1.0) / 2.0) {}
  double g1, g2, g3, g4, g5, g6, g7;
};

struct function_and_derivative {
  double value;
  double derivative;
};

/// f_K(p) of (4.6)-(4.7) for the side K with state `side` and sound speed a, and df_K/dp.
function_and_derivative pressure_function(double p, const riemann_state& side, double a, const gamma_constants& g) {
  if (p > side.P) {  // shock: Rankine-Hugoniot jump, A_K = 2/((gamma+1) rho_K), B_K = G6 p_K
    const double A = g.g5 / side.rho;
    const double B = g.g6 * side.P;
    const double root = std::sqrt(A / (B + p));
    return {(p - side.P) * root, root * (1.0 - 0.5 * (p - side.P) / (B + p))};
  }
  const double ratio = p / side.P;  // rarefaction: isentropic
  return {g.g4 * a * (std::pow(ratio, g.g1) - 1.0), std::pow(ratio, -g.g2) / (side.rho * a)};
}

/// Starting value of the Newton iteration: Toro's adaptive choice among the primitive-variable,
/// two-rarefaction and two-shock approximations (sec. 9.5.1 / subroutine GUESSP).
double initial_pressure_guess(const riemann_state& left, const riemann_state& right, double a_left, double a_right,
                              const gamma_constants& g) {
  const double density_sound = 0.25 * (left.rho + right.rho) * (a_left + a_right);
  const double p_pvrs = std::max(0.0, 0.5 * (left.P + right.P) + 0.5 * (left.v - right.v) * density_sound);
  const double p_min = std::min(left.P, right.P), p_max = std::max(left.P, right.P);
  if (p_max / p_min <= 2.0 && p_min <= p_pvrs && p_pvrs <= p_max) return p_pvrs;
  if (p_pvrs < p_min) {  // two-rarefaction approximation
    const double pq = std::pow(left.P / right.P, g.g1);
    const double u_star =
      (pq * left.v / a_left + right.v / a_right + g.g4 * (pq - 1.0)) / (pq / a_left + 1.0 / a_right);
    const double factor_left = 1.0 + g.g7 * (left.v - u_star) / a_left;
    const double factor_right = 1.0 + g.g7 * (u_star - right.v) / a_right;
    return 0.5 * (left.P * std::pow(factor_left, g.g3) + right.P * std::pow(factor_right, g.g3));
  }
  // two-shock approximation around the PVRS value
  const double weight_left = std::sqrt((g.g5 / left.rho) / (g.g6 * left.P + p_pvrs));
  const double weight_right = std::sqrt((g.g5 / right.rho) / (g.g6 * right.P + p_pvrs));
  return std::max(1e-12 * p_min,
                  (weight_left * left.P + weight_right * right.P - (right.v - left.v)) / (weight_left + weight_right));
}

void check_state(const riemann_state& state, const char* side) {
  const std::string where = std::string(side) + " state: ";
  if (!std::isfinite(state.rho) || !std::isfinite(state.v) || !std::isfinite(state.P))
    throw std::invalid_argument(where + "density, velocity and pressure must be finite");
  if (state.rho < 0.0) throw std::invalid_argument(where + "density must be >= 0");
  if (state.P < 0.0) throw std::invalid_argument(where + "pressure must be >= 0");
  if (state.rho == 0.0 && state.P != 0.0)
    throw std::invalid_argument(where + "a vacuum (density 0) must have pressure 0");
  if (state.rho > 0.0 && state.P == 0.0)
    throw std::invalid_argument(where + "pressure must be > 0 where the density is > 0");
}

constexpr riemann_state vacuum_state{0.0, 0.0, 0.0};

}  // namespace

double specific_internal_energy(const riemann_state& state, double gamma) {
  return state.rho > 0.0 ? state.P / ((gamma - 1.0) * state.rho) : 0.0;
}

riemann_solution::riemann_solution(const riemann_state& left, const riemann_state& right, double gamma)
    : left_(left), right_(right), gamma_(gamma) {
  if (!(gamma > 1.0)) throw std::invalid_argument("gamma must be > 1");
  check_state(left, "left");
  check_state(right, "right");
  if (left.rho == 0.0 && right.rho == 0.0)
    throw std::invalid_argument("both states are vacuum: there is nothing to solve");

  const gamma_constants g(gamma);
  sound_left_ = left.rho > 0.0 ? std::sqrt(gamma * left.P / left.rho) : 0.0;
  sound_right_ = right.rho > 0.0 ? std::sqrt(gamma * right.P / right.rho) : 0.0;
  constexpr double infinity = std::numeric_limits<double>::infinity();

  // Vacuum cases (sec. 4.6): a rarefaction whose tail is the vacuum front u_K -+ 2 a_K/(gamma-1).
  const double front_left = left.v + g.g4 * sound_left_;
  const double front_right = right.v - g.g4 * sound_right_;
  if (right.rho == 0.0) {
    vacuum_ = true;
    speeds_ = {left.v - sound_left_, front_left, front_left, infinity, infinity};
    return;
  }
  if (left.rho == 0.0) {
    vacuum_ = true;
    speeds_ = {-infinity, -infinity, front_right, front_right, right.v + sound_right_};
    return;
  }
  if (front_left <= front_right) {  // pressure positivity condition (4.40) fails
    vacuum_ = true;
    speeds_ = {left.v - sound_left_, front_left, 0.5 * (front_left + front_right), front_right, right.v + sound_right_};
    return;
  }

  // Newton iteration on f(p) = f_L(p) + f_R(p) + (u_R - u_L) = 0 (4.5). f is increasing and
  // concave, so iterates left of the root converge monotonically; a step to p <= 0 (possible
  // from the right) is replaced by a tenth of the previous value, which lies left of the root
  // after a few such steps.
  const double velocity_jump = right.v - left.v;
  double p = initial_pressure_guess(left, right, sound_left_, sound_right_, g);
  constexpr int max_iterations = 200;
  constexpr double tolerance = 1e-14;
  bool converged = false;
  for (iterations_ = 1; iterations_ <= max_iterations; ++iterations_) {
    const auto f_left = pressure_function(p, left, sound_left_, g);
    const auto f_right = pressure_function(p, right, sound_right_, g);
    double p_new = p - (f_left.value + f_right.value + velocity_jump) / (f_left.derivative + f_right.derivative);
    if (p_new <= 0.0) p_new = 0.1 * p;
    const double change = 2.0 * std::fabs(p_new - p) / (p_new + p);
    p = p_new;
    if (change < tolerance) {
      converged = true;
      break;
    }
  }
  if (!converged) throw std::runtime_error("exact Riemann solver: Newton iteration for p* did not converge");

  star_pressure_ = p;
  const auto f_left = pressure_function(p, left, sound_left_, g);
  const auto f_right = pressure_function(p, right, sound_right_, g);
  star_velocity_ = 0.5 * (left.v + right.v) + 0.5 * (f_right.value - f_left.value);

  // Left wave: shock density (4.50) and speed (4.52), or rarefaction (4.53)-(4.55).
  const double ratio_left = p / left.P;
  if (p > left.P) {
    left_wave_ = wave_kind::shock;
    star_density_left_ = left.rho * (ratio_left + g.g6) / (g.g6 * ratio_left + 1.0);
    const double shock = left.v - sound_left_ * std::sqrt(g.g2 * ratio_left + g.g1);
    speeds_.left_head = speeds_.left_tail = shock;
  } else {
    left_wave_ = wave_kind::rarefaction;
    star_density_left_ = left.rho * std::pow(ratio_left, 1.0 / gamma);
    speeds_.left_head = left.v - sound_left_;
    speeds_.left_tail = star_velocity_ - sound_left_ * std::pow(ratio_left, g.g1);
  }
  // Right wave: (4.57)-(4.59) or (4.60)-(4.63).
  const double ratio_right = p / right.P;
  if (p > right.P) {
    right_wave_ = wave_kind::shock;
    star_density_right_ = right.rho * (ratio_right + g.g6) / (g.g6 * ratio_right + 1.0);
    const double shock = right.v + sound_right_ * std::sqrt(g.g2 * ratio_right + g.g1);
    speeds_.right_head = speeds_.right_tail = shock;
  } else {
    right_wave_ = wave_kind::rarefaction;
    star_density_right_ = right.rho * std::pow(ratio_right, 1.0 / gamma);
    speeds_.right_head = right.v + sound_right_;
    speeds_.right_tail = star_velocity_ + sound_right_ * std::pow(ratio_right, g.g1);
  }
  speeds_.contact = star_velocity_;
}

riemann_state riemann_solution::sample_left(double s) const {
  const gamma_constants g(gamma_);
  if (s <= speeds_.left_head) return left_;
  if (s < speeds_.left_tail) {  // inside the left rarefaction fan (4.56)
    const double base = g.g5 + g.g6 / sound_left_ * (left_.v - s);
    return {left_.rho * std::pow(base, g.g4), g.g5 * (sound_left_ + g.g7 * left_.v + s),
            left_.P * std::pow(base, g.g3)};
  }
  if (vacuum_) return vacuum_state;
  return {star_density_left_, star_velocity_, star_pressure_};
}

riemann_state riemann_solution::sample_right(double s) const {
  const gamma_constants g(gamma_);
  if (s >= speeds_.right_head) return right_;
  if (s > speeds_.right_tail) {  // inside the right rarefaction fan (4.63)
    const double base = g.g5 - g.g6 / sound_right_ * (right_.v - s);
    return {right_.rho * std::pow(base, g.g4), g.g5 * (-sound_right_ + g.g7 * right_.v + s),
            right_.P * std::pow(base, g.g3)};
  }
  if (vacuum_) return vacuum_state;
  return {star_density_right_, star_velocity_, star_pressure_};
}

riemann_state riemann_solution::sample(double x_over_t) const {
  if (vacuum_) {
    if (left_.rho > 0.0 && x_over_t <= speeds_.left_tail) return sample_left(x_over_t);
    if (right_.rho > 0.0 && x_over_t >= speeds_.right_tail) return sample_right(x_over_t);
    return vacuum_state;
  }
  return x_over_t <= star_velocity_ ? sample_left(x_over_t) : sample_right(x_over_t);
}

riemann_solution solve_riemann_problem(const riemann_state& left, const riemann_state& right, double gamma) {
  return riemann_solution(left, right, gamma);
}

}  // namespace flecsph::analytic
