#!/usr/bin/python3
"""Why a bns inspiral runs ahead of Peters: its measured energy curve, power and spins (docs/bns.md).

Energy balance (Lai, Rasio & Shapiro 1994, ApJ 420, 811) writes the quasi-circular inspiral as
da/dt = -P(a) / (dE_eq/da): the time to reach a is t(a) = integral from a to a0 of (dE_eq/da') / P da'.
Peters' point masses have E_eq = -G m1 m2 / (2a) and P_Peters = (32/5) G^4 m1^2 m2^2 M / (c^5 a^5).
The run measures both factors itself, without a model: the energy it radiated to reach a
(E_rad(a) = E(a0) - E(a) to the balance tolerance of the run) against the point masses'
dE_pm = G m1 m2 (1/a - 1/a0) / 2, and the power P (`radiation_reaction_power`) against P_Peters(a).
Each factor alone gives a time to reach a:

    t(energy) = sum dE_rad / P_Peters(a)   (the run's energy curve, Peters' power)
    t(power)  = sum dE_pm(a) / P           (the point masses' energy curve, the run's power)

so the departure from Peters splits into the two. The separation is averaged over one orbit
(--average-orbits; the orbit's small eccentricity oscillates it) before the crossing of each
threshold is found. The lowest-order adiabatic tide (tidal_inspiral.py: E = -G M mu / (2a) + 2 T / a^6)
predicts E_rad / dE_pm; the stars' spins S_z (about each star's centre, from the H5Part particles)
against the release and corotation (I_zz Omega) test its "spins held fixed"; the orbit pays
Omega dS for a spin-up dS by the tidal torque (Omega - Omega_spin of it heats the star).

    inspiral_energy_budget.py run.h5part run.statistics.txt [--radii 3.8 3.5 3.3 3.2 3.1 3.0] [--average-orbits 1]

Exit 1 unless a threshold is reached and the columns are consistent: sum dE_rad / P must give back
the run's own time to each threshold within 1% (P is the derivative of E_rad).
"""
import argparse
import math
import os
import sys

import h5py
import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "tests", "validation"))
from check_peters_inspiral import attribute, peters_rate, read_statistics  # noqa: E402
from tidal_inspiral import N1_POLYTROPE_K2, tidal_energy  # noqa: E402

PROGRAM = "inspiral_energy_budget"


def orbit_averaged(t, a, phase, orbits):
    """a averaged in time over `orbits` orbits (unwrapped orbital phase) centred on each row; NaN
    where the window leaves the rows. orbits = 0: a itself."""
    if orbits == 0:
        return a.copy()
    half = math.pi * orbits
    integral = np.concatenate(([0.0], np.cumsum(0.5 * (a[1:] + a[:-1]) * np.diff(t))))
    start, end = np.interp(phase - half, phase, t), np.interp(phase + half, phase, t)
    mean = (np.interp(end, t, integral) - np.interp(start, t, integral)) / (end - start)
    mean[(phase - half < phase[0]) | (phase + half > phase[-1])] = np.nan
    return mean


def spins(path, release):
    """(t, S_z and I_zz of star 1, the same of star 2, orbital Omega, separation a, radial and
    tangential relative speeds of the centres) at every output step after the release."""
    rows = []
    with h5py.File(path, "r") as f:
        for name in sorted((k for k in f if k.startswith("Step#")), key=lambda k: int(k[5:])):
            step = f[name]
            time = float(np.ravel(step.attrs["time"])[0])
            if time < release:
                continue
            ids, mass = step["id"][()], step["m"][()]
            x = np.stack([step[k][()] for k in ("x", "y", "z")], axis=1)
            v = np.stack([step[k][()] for k in ("vx", "vy", "vz")], axis=1)
            centres, row = [], [time]
            for star in (ids < len(ids) // 2, ids >= len(ids) // 2):
                m = mass[star]
                X, V = m @ x[star] / m.sum(), m @ v[star] / m.sum()
                dx, dv = x[star] - X, v[star] - V
                centres.append((X, V))
                row += [m @ (dx[:, 0] * dv[:, 1] - dx[:, 1] * dv[:, 0]), m @ (dx[:, 0] ** 2 + dx[:, 1] ** 2)]
            d, w = centres[1][0] - centres[0][0], centres[1][1] - centres[0][1]
            a = np.linalg.norm(d)
            radial = w @ d / a
            rows.append(row + [(d[0] * w[1] - d[1] * w[0]) / a**2, a, radial, np.linalg.norm(w - radial * d / a)])
    return np.array(rows)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("h5part")
    parser.add_argument("statistics")
    parser.add_argument("--radii", type=float, nargs="+", default=[3.8, 3.5, 3.3, 3.2, 3.1, 3.0])
    parser.add_argument("--average-orbits", type=float, default=1.0)
    args = parser.parse_args()

    with h5py.File(args.h5part, "r") as f:
        attributes = {k: f.attrs[k] for k in f.attrs}
    G, c = attribute(attributes, "gravitational_constant", PROGRAM), attribute(attributes, "speed_of_light", PROGRAM)
    m1, m2 = attribute(attributes, "star_mass", PROGRAM), attribute(attributes, "companion_mass", PROGRAM)
    radius = attribute(attributes, "star_radius", PROGRAM)
    if abs(m1 / m2 - 1) > 1e-12:
        sys.exit(f"{PROGRAM}: the tidal columns are for equal masses (star_mass {m1}, companion_mass {m2})")
    rows = read_statistics(args.statistics)
    acting = (rows["relaxing"] == 0) & (rows["radiation_reaction_on"] == 1)
    if np.count_nonzero(acting) < 3:
        sys.exit(f"{PROGRAM}: fewer than 3 statistics rows with the radiation reaction acting")
    t, a, power = rows["time"][acting], rows["separation"][acting], rows["radiation_reaction_power"][acting]
    radiated = rows["radiated_energy"][acting] - rows["radiated_energy"][acting][0]
    phase = np.unwrap(rows["orbital_phase"][acting])
    mean = orbit_averaged(t, a, phase, args.average_orbits)
    a0 = a[0]
    # The energy curve is measured from the first averaged row (half an orbit after the release):
    # the release is at an extreme of the oscillation, so a0 is not the orbit's mean separation.
    reference = np.nonzero(np.isfinite(mean))[0]
    if not reference.size:
        sys.exit(f"{PROGRAM}: the run holds no window of {args.average_orbits:g} orbit(s) after the release")
    reference = reference[0]

    def point_mass(x):  # dE_pm from a0 to x
        return G * m1 * m2 * (1 / x - 1 / a0) / 2

    def peters_power(x):
        return 32 / 5 * G**4 * (m1 * m2) ** 2 * (m1 + m2) / (c**5 * x**5)

    spin = spins(args.h5part, t[0])
    mid = 0.5 * (a[1:] + a[:-1])
    # The power over an orbit against Peters' over the same orbit (both oscillate with a).
    power_ratio = orbit_averaged(t, power, phase, args.average_orbits) / orbit_averaged(
        t, peters_power(a), phase, args.average_orbits)
    print(f"released at t0 = {t[0]:.6g}, a0 = {a0 / radius:.4f} R; separation averaged over "
          f"{args.average_orbits:g} orbit(s); energy curve from t = {t[reference]:.6g}, "
          f"a = {mean[reference] / radius:.4f} R; spins S0 = {spin[0, 1]:.5g}, {spin[0, 3]:.5g} at t = {spin[0, 0]:.6g}")
    print("a < (R) | t - t0 SPH | Peters | t(energy) | t(power) | E_rad/dE_pm | tide k2 | P/P_Peters | tide k2"
          " | S/S0 | S/(I Omega) | Omega dS/dE_pm")
    failures, reached = [], 0
    for threshold in args.radii:
        below = np.nonzero(mean <= threshold * radius)[0]
        if not below.size:
            continue
        i = below[0]
        reached += 1
        x = mean[i]
        t_run = t[i] - t[0]
        t_peters = (a0**4 - x**4) / peters_rate(G, c, m1, m2)
        t_energy = np.sum(np.diff(radiated[: i + 1]) / peters_power(mid[:i]))
        t_power = np.sum(np.diff(point_mass(a[: i + 1])) / (0.5 * (power[1 : i + 1] + power[:i])))
        t_power += (point_mass(x) - point_mass(a[i])) / power[i]  # from the row's a to the mean x
        t_self = np.sum(np.diff(radiated[: i + 1]) / (0.5 * (power[1 : i + 1] + power[:i])))
        if abs(t_self / t_run - 1) > 0.01:
            failures.append(f"sum dE_rad / P = {t_self:.6g} against the run's {t_run:.6g} at {threshold} R")
        x0 = mean[reference]
        curve = point_mass(x) - point_mass(x0)
        tide = tidal_energy(x0, G, m1, radius, N1_POLYTROPE_K2) - tidal_energy(x, G, m1, radius, N1_POLYTROPE_K2)
        k = min(np.searchsorted(spin[:, 0], t[i]), len(spin) - 1)
        s, s0 = 0.5 * (spin[k, 1] + spin[k, 3]), 0.5 * (spin[0, 1] + spin[0, 3])
        corotation = s / (0.5 * (spin[k, 2] + spin[k, 4]) * spin[k, 5])
        # The orbit's energy given to the spins by the tidal torque: sum Omega dS over the steps.
        k0 = min(np.searchsorted(spin[:, 0], t[reference]), k)
        total = spin[k0 : k + 1, 1] + spin[k0 : k + 1, 3]
        paid = np.sum(0.5 * (spin[k0 + 1 : k + 1, 5] + spin[k0:k, 5]) * np.diff(total))
        # The model's power on its circle: v^2 = G M / a (1 + eps), eps = 12 k2 (R/a)^5 for equal stars,
        # in the reaction's (6 v^2 - 2 G M / a) v^2 (tidal_inspiral.py), over Peters' 4 (G M / a)^2.
        eps = 12 * N1_POLYTROPE_K2 * (radius / x) ** 5
        tide_power = (6 * (1 + eps) - 2) * (1 + eps) / 4
        print(f"{threshold:7.2f} | {t_run:10.4g} | {t_peters:6.4g} | {t_energy:9.4g} | {t_power:8.4g} | "
              f"{(radiated[i] - radiated[reference]) / curve:11.4f} | {tide / curve:7.4f} | "
              f"{power_ratio[i]:10.4f} | {tide_power:7.4f}"
              f" | {s / s0:5.3f} | {corotation:11.3f} | {paid / curve:14.4f}")
    # The plunge (Lai, Rasio & Shapiro 1994 find a radial infall ~10% of the orbital speed just
    # before contact): the last output step before contact against Peters' circular inspiral there.
    apart = np.nonzero((spin[:, 6] > 2 * radius) & (spin[:, 0] <= t[-1]))[0]
    contact = np.any((rows["relaxing"] == 0) & (rows["radiation_reaction_on"] == 0) & (rows["time"] > t[0]))
    if contact and apart.size:
        k = apart[-1]
        x = spin[k, 6]
        peters_ratio = 64 / 5 * G**3 * m1 * m2 * (m1 + m2) / (c**5 * x**3) / math.sqrt(G * (m1 + m2) / x)
        print(f"last output step before contact: t = {spin[k, 0]:.6g}, a = {x / radius:.4f} R: radial / tangential "
              f"speed of the centres {-spin[k, 7] / spin[k, 8]:.4f} (Peters' circular inspiral: {peters_ratio:.4f})")
    if not reached:
        failures.append(f"the averaged separation reaches none of {args.radii} R")
    if failures:
        sys.exit(f"{PROGRAM}: " + "; ".join(failures))


if __name__ == "__main__":
    main()
