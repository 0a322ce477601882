"""The linear growth rate of the Rayleigh-Taylor set-up (rt_profile.py) at k = 2 pi / W, computed
here for the growth-rate check (the issue asks for the linear theory of the set-up):

* the incompressible sharp interface, sigma = sqrt(A k g tanh(k H / 2)) (Chandrasekhar 1961, ch. X);
* the smooth profile, incompressible and compressible: the eigenvalue sigma^2 of the linearised
  equations of the hydrostatic state rho(y), P(y) between the walls, for the Lagrangian
  displacement xi_y(y) and the Eulerian pressure p(y) of a mode exp(i k x + sigma t), adiabatic
  with gamma (e.g. Chandrasekhar 1961, ch. X, eq. 21 in the incompressible limit):

      div xi = (rho g xi_y - p) / (gamma P)
      xi_y'  = div xi - k^2 p / (rho sigma^2)
      p'     = -rho sigma^2 xi_y + g (rho div xi + rho' xi_y)

  with xi_y = 0 at both walls; 1 / (gamma P) = 0 gives the incompressible equation (rho xi')' -
  k^2 rho xi = -(g k^2 / sigma^2) rho' xi. Shooting from y = 0 (xi_y = 0, p = 1); the growth rate
  is the largest sigma at which xi_y(H) = 0 (scanned downwards, then Brent's method).

    rt_linear_theory.py [--set key=value ...] [--json FILE]

Checks itself first on the exponential profile rho = rho1 exp(beta y) between walls a distance H
apart (incompressible), whose rate is known exactly: sigma^2 = g beta k^2 / (k^2 + beta^2 / 4 +
pi^2 / H^2) (Chandrasekhar 1961, ch. X, sec. 92); exits 1 beyond 1e-6 relative.
"""
import argparse
import json
import os
import sys

import numpy as np
from scipy.integrate import solve_ivp
from scipy.optimize import brentq

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import rt_profile  # noqa: E402


def wall_residual(sigma, setup, compressible):
    """xi_y at the top wall of the solution with xi_y = 0, p = 1 at the bottom wall, over the
    largest |xi_y| on the way (so that the scale of the shooting does not matter)."""
    k, g, s2 = setup.wave_number, setup.uniform_gravity, sigma * sigma

    def rhs(y, state):
        xi, p = state
        rho = setup.density(y)
        divergence = (rho * g * xi - p) / (setup.gamma * setup.pressure_at(y)) if compressible else 0.0
        return [divergence - k * k * p / (rho * s2), -rho * s2 * xi + g * (rho * divergence + setup.density_slope(y) * xi)]

    solution = solve_ivp(rhs, (0.0, setup.height), [0.0, 1.0], rtol=1e-10, atol=1e-14, method="DOP853",
                         max_step=setup.smoothing / 4, dense_output=False)
    xi = solution.y[0]
    return xi[-1] / np.max(np.abs(xi))


def growth_rate(setup, compressible=True, points=30):
    """The largest sigma with a solution vanishing at both walls."""
    top = 1.5 * setup.sharp_rate()
    grid = np.linspace(top, 0.05 * top, points)
    values = [wall_residual(s, setup, compressible) for s in grid]
    for i in range(1, len(grid)):
        if np.sign(values[i]) != np.sign(values[i - 1]):
            return brentq(wall_residual, grid[i], grid[i - 1], args=(setup, compressible), xtol=1e-10)
    sys.exit("rt_linear_theory: no growing mode between %g and %g" % (grid[-1], grid[0]))


class ExponentialSetUp(rt_profile.SetUp):
    """rho = rho1 exp(beta y) with beta = ln(rho2 / rho1) / H: the solver's check."""

    def __init__(self, **overrides):
        super().__init__(**overrides)
        self.beta = np.log(self.rho2 / self.rho1) / self.height

    def density(self, y):
        return self.rho1 * np.exp(self.beta * y)

    def density_slope(self, y):
        return self.beta * self.density(y)

    def exact_rate(self):
        k, b = self.wave_number, self.beta
        return float(np.sqrt(self.uniform_gravity * b * k * k / (k * k + b * b / 4 + (np.pi / self.height) ** 2)))


def rates(setup):
    """{name: growth rate} of the set-up: sharp, incompressible and compressible smooth profile."""
    return {"sharp_incompressible": setup.sharp_rate(),
            "smooth_incompressible": growth_rate(setup, compressible=False),
            "smooth_compressible": growth_rate(setup, compressible=True)}


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--set", action="append", default=[], help="key=value of rt_profile.DEFAULTS")
    parser.add_argument("--json")
    arguments = parser.parse_args()
    overrides = {key: float(value) for key, value in (item.split("=", 1) for item in arguments.set)}
    exponential = ExponentialSetUp(**overrides)
    check = growth_rate(exponential, compressible=False) / exponential.exact_rate() - 1
    print("Solver check, exponential profile rho1 exp(beta y), incompressible: %.8f against exactly %.8f (%+.1e)" %
          (exponential.exact_rate() * (1 + check), exponential.exact_rate(), check))
    if abs(check) > 1e-6:
        sys.exit("rt_linear_theory: the solver misses the exponential profile's exact rate")
    setup = rt_profile.SetUp(**overrides)
    result = rates(setup)
    print("Rayleigh-Taylor, k = %.5f, A = %.4f, g = %g, Delta = %g, gamma = %g, P0 = %g: growth rate %.5f "
          "(smooth, compressible), %.5f (smooth, incompressible), %.5f (sharp, incompressible)" %
          (setup.wave_number, setup.atwood, setup.uniform_gravity, setup.smoothing, setup.gamma, setup.pressure,
           result["smooth_compressible"], result["smooth_incompressible"], result["sharp_incompressible"]))
    if arguments.json:
        with open(arguments.json, "w") as out:
            json.dump(result, out, indent=1)


if __name__ == "__main__":
    main()
