// The rows' SPH density, h, Omega and equilibrium pressure (discrete_equilibrium.hh).
#include "discrete_equilibrium.hh"

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace rayleigh_taylor {

namespace {
/// f(r, dy) summed over the particles of row `b` seen from one particle of row `a`, within 2h.
template<class Function>
double lattice_sum(const row& a, const row& b, double width, double h, Function&& f) {
  const double spacing = width / double(a.count), dy = a.y - b.y, reach = flecsph::physics::kernel_support * h;
  if (std::fabs(dy) >= reach) return 0;
  const double offset = b.shift - a.shift;  // x_b - x_a = (i + offset) spacing
  double sum = 0;
  for (auto i = std::int64_t(std::floor(-reach / spacing - offset)); double(i) + offset <= reach / spacing; ++i) {
    const double dx = (double(i) + offset) * spacing, r = std::sqrt(dx * dx + dy * dy);
    if (r < reach) sum += f(r, dy);
  }
  return sum;
}

/// Gaussian elimination with partial pivoting of the dense n x n system A x = b (A row-major).
std::vector<double> solve(std::vector<double> A, std::vector<double> b) {
  const std::size_t n = b.size();
  for (std::size_t c = 0; c < n; ++c) {
    std::size_t pivot = c;
    for (std::size_t r = c + 1; r < n; ++r)
      if (std::fabs(A[r * n + c]) > std::fabs(A[pivot * n + c])) pivot = r;
    if (A[pivot * n + c] == 0) throw std::runtime_error("rayleigh_taylor: singular equilibrium system");
    for (std::size_t k = 0; k < n; ++k) std::swap(A[c * n + k], A[pivot * n + k]);
    std::swap(b[c], b[pivot]);
    for (std::size_t r = c + 1; r < n; ++r) {
      const double factor = A[r * n + c] / A[c * n + c];
      if (factor == 0) continue;
      for (std::size_t k = c; k < n; ++k) A[r * n + k] -= factor * A[c * n + k];
      b[r] -= factor * b[c];
    }
  }
  std::vector<double> x(n);
  for (std::size_t c = n; c-- > 0;) {
    double sum = b[c];
    for (std::size_t k = c + 1; k < n; ++k) sum -= A[c * n + k] * x[k];
    x[c] = sum / A[c * n + c];
  }
  return x;
}
}  // namespace

std::vector<row_state> discrete_equilibrium(const std::vector<row>& rows, double mass, const problem& p,
                                            const sph::physics_settings& physics) {
  for (const row& r : rows)
    if (r.count != rows.front().count) throw std::logic_error("rayleigh_taylor: the equilibrium needs one row count");
  const std::size_t n = rows.size();
  std::vector<row_state> state(n);
  return flecsph::physics::dispatch_kernel<2>(physics.kernel, [&](auto kernel) {
    using K = decltype(kernel);
    // The rows within reach of row a (rows are sorted by y).
    const auto near = [&](std::size_t a, double h) {
      std::size_t first = a, last = a;
      while (first > 0 && rows[a].y - rows[first - 1].y < flecsph::physics::kernel_support * h) --first;
      while (last + 1 < n && rows[last + 1].y - rows[a].y < flecsph::physics::kernel_support * h) ++last;
      return std::make_pair(first, last);
    };
    const auto density_sums = [&](std::size_t a, double h, double& rho, double& drho_dh) {
      rho = drho_dh = 0;
      const auto [first, last] = near(a, h);
      for (std::size_t b = first; b <= last; ++b) {
        rho += mass * lattice_sum(rows[a], rows[b], p.width, h, [&](double r, double) { return K::value(r, h); });
        drho_dh +=
          mass * lattice_sum(rows[a], rows[b], p.width, h, [&](double r, double) { return K::h_derivative(r, h); });
      }
    };
    // Density, h and Omega as the density task finds them (walls: their h, Omega = 1).
    for (std::size_t a = 0; a < n; ++a) {
      row_state& s = state[a];
      s.h = physics.eta * std::sqrt(mass / density(rows[a].y, p));
      double drho_dh = 0;
      const bool adapt = physics.adaptive_smoothing_length && !rows[a].wall;
      for (int iteration = 0;; ++iteration) {
        density_sums(a, s.h, s.rho, drho_dh);
        if (!adapt) break;
        if (std::fabs(flecsph::physics::smoothing_length_residual<2>(s.h, s.rho, mass, physics.eta)) < 1e-13 ||
            iteration == 100)
          break;
        s.h = flecsph::physics::smoothing_length_newton_step<2>(s.h, s.rho, drho_dh, mass, physics.eta);
      }
      s.omega = adapt ? flecsph::physics::grad_h_omega<2>(s.h, s.rho, drho_dh) : 1.0;
      s.pressure = hydrostatic_pressure(rows[a].y, p);
    }
    // dv_y/dt of a fluid row = -sum_b m [p_a F_a + p_b F_b] dy - g = 0 with p = P / (Omega rho^2):
    // linear in the fluid rows' P; the walls' P are known.
    std::vector<std::size_t> unknown(n, n);
    std::size_t count = 0;
    for (std::size_t a = 0; a < n; ++a)
      if (!rows[a].wall) unknown[a] = count++;
    std::vector<double> A(count * count, 0.0), rhs(count, p.gravity);
    double h_largest = 0;
    for (const row_state& s : state) h_largest = std::max(h_largest, s.h);
    for (std::size_t a = 0; a < n; ++a) {
      if (rows[a].wall) continue;
      const auto [first, last] = near(a, h_largest);
      for (std::size_t b = first; b <= last; ++b) {
        const double own = lattice_sum(rows[a], rows[b], p.width, state[a].h,
                                       [&](double r, double dy) { return K::gradient_factor(r, state[a].h) * dy; });
        const double their = lattice_sum(rows[a], rows[b], p.width, state[b].h,
                                         [&](double r, double dy) { return K::gradient_factor(r, state[b].h) * dy; });
        A[unknown[a] * count + unknown[a]] -= mass * own / (state[a].omega * state[a].rho * state[a].rho);
        const double coefficient = -mass * their / (state[b].omega * state[b].rho * state[b].rho);
        if (rows[b].wall)
          rhs[unknown[a]] -= coefficient * state[b].pressure;
        else
          A[unknown[a] * count + unknown[b]] += coefficient;
      }
    }
    // The exact solution zigzags from row to row (+-10% where the rows are closer than their
    // particles: a zigzag is nearly in the null space of the SPH gradient), an entropy zigzag whose
    // buoyancy holds the interface. So: least squares of the accelerations plus lambda times the
    // second differences of P - P(y), lambda = 1e-6 of the scale of A^T A (regularisation).
    std::vector<double> deviation(count * count, 0.0);  // D^T D of the second differences
    for (std::size_t r = 1; r + 1 < count; ++r) {
      const double c[3] = {1, -2, 1};
      for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 3; ++j) deviation[(r - 1 + i) * count + (r - 1 + j)] += c[i] * c[j];
    }
    std::vector<double> hydrostatic(count);
    for (std::size_t a = 0; a < n; ++a)
      if (!rows[a].wall) hydrostatic[unknown[a]] = state[a].pressure;
    std::vector<double> normal(count * count, 0.0), right(count, 0.0);
    double scale = 0;
    for (std::size_t i = 0; i < count; ++i)
      for (std::size_t j = 0; j < count; ++j) {
        double sum = 0;
        for (std::size_t k = 0; k < count; ++k) sum += A[k * count + i] * A[k * count + j];
        normal[i * count + j] = sum;
      }
    for (std::size_t i = 0; i < count; ++i) scale += normal[i * count + i];
    const double lambda = 1e-6 * scale / double(count);
    for (std::size_t i = 0; i < count; ++i) {
      for (std::size_t k = 0; k < count; ++k) right[i] += A[k * count + i] * rhs[k];
      for (std::size_t j = 0; j < count; ++j) {
        normal[i * count + j] += lambda * deviation[i * count + j];
        right[i] += lambda * deviation[i * count + j] * hydrostatic[j];
      }
    }
    const auto pressure = solve(std::move(normal), std::move(right));
    for (std::size_t a = 0; a < n; ++a)
      if (!rows[a].wall) state[a].pressure = pressure[unknown[a]];
    return state;
  });
}

}  // namespace rayleigh_taylor
