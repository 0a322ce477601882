// Composite Gauss-Legendre quadrature on [a, b] (nodes by Newton iteration on P_n; Press et al.,
// Numerical Recipes, sec. 4.6), for the energy integrals of the exact solutions and the tests.
#pragma once

#include <cmath>
#include <stdexcept>
#include <vector>

namespace flecsph::analytic {

/// Nodes and weights of the n-point Gauss-Legendre rule on [-1, 1]; exact for polynomials of
/// degree 2n - 1.
struct gauss_legendre_rule {
  std::vector<double> nodes;
  std::vector<double> weights;

  explicit gauss_legendre_rule(int points) : nodes(points), weights(points) {
    if (points < 1) throw std::invalid_argument("Gauss-Legendre rule needs at least 1 point");
    constexpr double pi = 3.14159265358979323846;
    for (int i = 0; i < (points + 1) / 2; ++i) {
      // Start from Tricomi's approximation of the i-th root, polish with Newton on P_n.
      double x = std::cos(pi * (i + 0.75) / (points + 0.5));
      double derivative = 1.0;
      for (int iteration = 0; iteration < 100; ++iteration) {
        double p_current = 1.0, p_previous = 0.0;
        for (int k = 1; k <= points; ++k) {  // three-term recurrence for P_k(x)
          const double p_older = p_previous;
          p_previous = p_current;
          p_current = ((2.0 * k - 1.0) * x * p_previous - (k - 1.0) * p_older) / k;
        }
        derivative = points * (x * p_current - p_previous) / (x * x - 1.0);
        const double step = p_current / derivative;
        x -= step;
        if (std::fabs(step) < 1e-16) break;
      }
      nodes[i] = -x;
      nodes[points - 1 - i] = x;
      weights[i] = weights[points - 1 - i] = 2.0 / ((1.0 - x * x) * derivative * derivative);
    }
  }
};

/// Integral of f over [a, b] with `panels` equal panels, each with `rule`.
template<class Function>
double integrate(Function&& f, double a, double b, int panels, const gauss_legendre_rule& rule) {
  const double width = (b - a) / panels;
  double sum = 0.0;
  for (int panel = 0; panel < panels; ++panel) {
    const double middle = a + (panel + 0.5) * width;
    double panel_sum = 0.0;
    for (std::size_t i = 0; i < rule.nodes.size(); ++i)
      panel_sum += rule.weights[i] * f(middle + 0.5 * width * rule.nodes[i]);
    sum += 0.5 * width * panel_sum;
  }
  return sum;
}

}  // namespace flecsph::analytic
