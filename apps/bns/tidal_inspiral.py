#!/usr/bin/python3
"""The inspiral of two equal stars with adiabatic quadrupole tides, against the SPH run and Peters.

Why: the SPH separation runs ahead of Peters' point masses below ~3.3 R (docs/bns.md). Point masses
lack the tidal attraction. This script integrates the lowest-order (Newtonian, adiabatic,
quadrupole) tidal model of two equal stars of mass m and radius R on a circular orbit and asks how
much of the SPH run's departure from Peters it accounts for.

Model (Lai, Rasio & Shapiro 1993, ApJS 88, 205 for the energy; Flanagan & Hinderer 2008, PRD 77,
021502 for the adiabatic Lagrangian): each star's induced quadrupole Q_ij = -lambda E_ij in the
companion's tidal field E_ij = G m / a^3 (delta_ij - 3 n_i n_j), lambda = (2/3) k2 R^5 / G, adds
the potential -k2 G m^2 R^5 / a^6 per star. With T = 2 k2 G m^2 R^5, M = 2m, mu = m/2:

    V(a) = -G M mu / a - T / a^6,      mu omega^2 a = dV/da,
    E(a) = -G M mu / (2a) + 2 T / a^6, dE/da = G M mu / (2 a^2) - 12 T / a^7.

The stars' spins are held fixed (the viscosity too small to keep them corotating as the orbit
shrinks), so no spin energy enters dE/da. The orbit loses energy at the rate the code's
radiation reaction removes on a circle (physics/radiation_reaction.hh, Kidder 1995 point masses,
evaluated at the model's v^2 = omega^2 a^2): P = (8/5) G^2 M mu^2 / (c^5 a^3) (6 v^2 - 2 G M / a) v^2,
which is Peters' (32/5) G^4 M^3 mu^2 / (c^5 a^5) when v^2 = G M / a. Then da/dt = -P / (dE/da).
k2 = (15 - pi^2) / (2 pi^2) = 0.2599 for an n = 1 polytrope (Hinderer 2008, ApJ 677, 1216).

    tidal_inspiral.py run.h5part run.statistics.txt [--k2 0.2599] [--radii 3.8 3.5 3.3 3.2 3.1 3.0]

Prints, for each separation threshold, the largest |a / a_model - 1| of the SPH run against
Peters and against the tidal model while a > threshold R, and the contact (a = 2 R) times.
"""
import argparse
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tests", "validation"))
from check_peters_inspiral import (after_release, attribute, peters_rate, peters_separation,  # noqa: E402
                                   read_statistics, separations)

PROGRAM = "tidal_inspiral"
N1_POLYTROPE_K2 = (15 - math.pi**2) / (2 * math.pi**2)


def tidal_energy(a, G, m, radius, k2):
    """E(a) of the model's circular orbit (two equal stars, spins fixed): -G M mu / (2a) + 2 T / a^6."""
    return -G * m * m / (2 * a) + 4 * k2 * G * m * m * radius**5 / a**6


def tidal_separation(t, a0, G, c, m, radius, k2):
    """a(t) of the tidal model from a0 at t[0] (NaN after contact, a = 2 R) and the time of contact
    (None if after t[-1]), by 4th-order Runge-Kutta on a grid 20 times finer than t."""
    M, mu = 2 * m, m / 2
    T = 2 * k2 * G * m * m * radius**5

    def rate(a):
        v2 = G * M / a + 6 * T / (mu * a**6)
        power = 1.6 * G * G * M * mu * mu / (c**5 * a**3) * (6 * v2 - 2 * G * M / a) * v2
        slope = G * M * mu / (2 * a * a) - 12 * T / a**7
        return -power / slope if slope > 0 else -math.inf

    grid = np.linspace(t[0], t[-1], 20 * len(t) + 1)
    a = np.empty_like(grid)
    a[0] = a0
    for i in range(1, len(grid)):
        h, x = grid[i] - grid[i - 1], a[i - 1]
        k1 = rate(x)
        k2_ = rate(x + 0.5 * h * k1)
        k3 = rate(x + 0.5 * h * k2_)
        k4 = rate(x + h * k3)
        a[i] = x + h * (k1 + 2 * k2_ + 2 * k3 + k4) / 6
        if not (a[i] > 2 * radius):  # contact: the model ends there
            contact = grid[i - 1] + h * (x - 2 * radius) / (x - a[i]) if np.isfinite(a[i]) else grid[i]
            a[i:] = np.nan
            return np.interp(t, grid, a), contact
    return np.interp(t, grid, a), None


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("h5part")
    parser.add_argument("statistics")
    parser.add_argument("--k2", type=float, default=N1_POLYTROPE_K2, help="the stars' tidal Love number")
    parser.add_argument("--radii", type=float, nargs="+", default=[3.8, 3.5, 3.3, 3.2, 3.1, 3.0])
    args = parser.parse_args()

    times, distances, attributes = separations(args.h5part)
    G = attribute(attributes, "gravitational_constant", PROGRAM)
    c = attribute(attributes, "speed_of_light", PROGRAM)
    m1, m2 = attribute(attributes, "star_mass", PROGRAM), attribute(attributes, "companion_mass", PROGRAM)
    radius = attribute(attributes, "star_radius", PROGRAM)
    if abs(m1 / m2 - 1) > 1e-12:
        sys.exit(f"{PROGRAM}: the model is for equal masses (star_mass {m1}, companion_mass {m2})")
    _, t, a = after_release(times, distances, read_statistics(args.statistics), PROGRAM)
    rate = peters_rate(G, c, m1, m2)
    peters = peters_separation(t, a[0], rate)
    tidal, tidal_contact = tidal_separation(t, a[0], G, c, m1, radius, args.k2)
    # The integrator checked on the case with a closed form: without tides the model is Peters.
    untidal, _ = tidal_separation(t, a[0], G, c, m1, radius, 0.0)
    finite = np.isfinite(untidal)
    integrator_error = float(np.max(np.abs(untidal[finite] / peters[finite] - 1)))
    print(f"integrator check: the model with k2 = 0 against Peters' closed form: {integrator_error:.2e}")
    if integrator_error > 1e-6:
        sys.exit(f"{PROGRAM}: the k2 = 0 model departs from Peters by {integrator_error:.2e} > 1e-6")

    print(f"k2 = {args.k2:.4f}; from t0 = {t[0]:.6g}, a0 = {a[0] / radius:.4f} R")
    print("a > (R) | to t    | largest |a/a_Peters - 1| | largest |a/a_tidal - 1|")
    for threshold in args.radii:
        window = (a > threshold * radius) & np.isfinite(tidal)
        if not window.any():
            continue
        last = np.nonzero(window)[0][-1]
        peters_error = np.max(np.abs(a[window] / peters[window] - 1))
        tidal_error = np.max(np.abs(a[window] / tidal[window] - 1))
        print(f"{threshold:7.2f} | {t[last]:7.4g} | {peters_error:24.3%} | {tidal_error:23.3%}")
    contact = np.nonzero(a <= 2 * radius)[0]
    print("contact (a = 2 R): SPH " + (f"t = {t[contact[0]]:.6g}" if contact.size else "not reached") +
          ", tidal model " + (f"t = {tidal_contact:.6g}" if tidal_contact is not None else "not reached") +
          f", Peters t = {t[0] + (a[0] ** 4 - (2 * radius) ** 4) / rate:.6g}")


if __name__ == "__main__":
    main()
