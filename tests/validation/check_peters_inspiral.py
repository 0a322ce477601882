#!/usr/bin/python3
"""Checks a bns inspiral with radiation reaction against Peters (1964).

From the particles of the H5Part output (not the app's own columns): the two stars' centres of mass
by particle id (the first half of the ids is star 1), their separation a(t) at every output step
after the release (the first statistics row with relaxing = 0), against Peters' circular inspiral
from the first of those steps,

    a(t)^4 = a0^4 - (256/5) G^3 m1 m2 (m1 + m2) (t - t0) / c^5,

with G, c, the masses and R from the file's root attributes. While a > --until R (3 by default:
beyond it the tides take over) |a / a_Peters - 1| must stay within --bound (0.03). The orbit must
have shrunk by at least --shrink (0.01) of a0, so that the comparison sees the radiation reaction.
From the statistics rows after the release: the gravitational-wave frequency (the unwrapped phase of
h+ + i hx) over twice the orbital frequency (the unwrapped orbital phase) must be 1 within
--frequency-bound (0.01). When the run reaches contact (a = 2 R) its time is printed beside Peters'.

    check_peters_inspiral.py run.h5part run.statistics.txt [--bound 0.03] [--until 3]
"""
import argparse
import math
import sys

import h5py
import numpy as np


def read_statistics(path):
    names = None
    rows = []
    with open(path) as f:
        for line in f:
            if line.startswith("#"):
                names = line[1:].split()
                continue
            if line.strip():
                rows.append([float(v) for v in line.split()])
    if names is None or not rows:
        sys.exit(f"check_peters_inspiral: '{path}' holds no column line or no rows")
    table = np.array(rows)
    return {name: table[:, i] for i, name in enumerate(names)}


def separations(path):
    """(time, separation) of every output step, and the root attributes."""
    with h5py.File(path, "r") as f:
        attributes = {k: f.attrs[k] for k in f.attrs}
        steps = sorted((k for k in f.keys() if k.startswith("Step#")), key=lambda k: int(k[5:]))
        times, distances = [], []
        for name in steps:
            step = f[name]
            ids = step["id"][()]
            half = len(ids) // 2
            mass = step["m"][()]
            position = np.stack([step[axis][()] for axis in ("x", "y", "z")], axis=1)
            first = ids < half
            centres = [np.sum(mass[sel, None] * position[sel], axis=0) / np.sum(mass[sel]) for sel in (first, ~first)]
            times.append(float(np.ravel(step.attrs["time"])[0]))
            distances.append(float(np.linalg.norm(centres[1] - centres[0])))
    return np.array(times), np.array(distances), attributes


def attribute(attributes, name, program="check_peters_inspiral"):
    if name not in attributes:
        sys.exit(f"{program}: the output has no root attribute '{name}' (run with radiation_reaction = true)")
    return float(np.ravel(attributes[name])[0])


def after_release(times, distances, rows, program="check_peters_inspiral"):
    """The release time (the first statistics row with relaxing = 0) and (t, a) of the output steps
    from it on."""
    released = rows["relaxing"] == 0
    if not released.any():
        sys.exit(f"{program}: the statistics rows never leave the relaxation")
    release = rows["time"][np.argmax(released)]
    after = times >= release
    if np.count_nonzero(after) < 3:
        sys.exit(f"{program}: fewer than 3 output steps after the release at t = {release}")
    return release, times[after], distances[after]


def peters_rate(G, c, m1, m2):
    """-d(a^4)/dt of a circular point-mass inspiral (Peters 1964)."""
    return 256.0 / 5.0 * G**3 * m1 * m2 * (m1 + m2) / c**5


def peters_separation(t, a0, rate):
    """Peters' a(t) from a0 at t[0], zero after coalescence."""
    return np.maximum(a0**4 - rate * (t - t[0]), 0.0) ** 0.25


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("h5part")
    parser.add_argument("statistics")
    parser.add_argument("--bound", type=float, default=0.03)
    parser.add_argument("--until", type=float, default=3.0, help="compare while a > this many star radii")
    parser.add_argument("--shrink", type=float, default=0.01)
    parser.add_argument("--frequency-bound", type=float, default=0.01)
    args = parser.parse_args()

    times, distances, attributes = separations(args.h5part)
    G = attribute(attributes, "gravitational_constant")
    c = attribute(attributes, "speed_of_light")
    m1 = attribute(attributes, "star_mass")
    m2 = attribute(attributes, "companion_mass")
    radius = attribute(attributes, "star_radius")
    rows = read_statistics(args.statistics)
    released = rows["relaxing"] == 0
    release, t, a = after_release(times, distances, rows)
    rate = peters_rate(G, c, m1, m2)
    peters = peters_separation(t, a[0], rate)
    compared = a > args.until * radius
    errors = np.abs(a[compared] / peters[compared] - 1)
    failures = []
    worst = float(np.max(errors))
    last = np.nonzero(compared)[0][-1]
    print(f"released at t = {release:.6g}; from t0 = {t[0]:.6g}, a0 = {a[0]:.6g} ({a[0] / radius:.4f} R): "
          f"{np.count_nonzero(compared)} output steps with a > {args.until} R, to t = {t[last]:.6g}: "
          f"a = {a[last]:.6g}, Peters {peters[last]:.6g}; largest |a / a_Peters - 1| = {worst:.3e}")
    if worst > args.bound:
        failures.append(f"the separation departs from Peters' by {worst:.3e} > {args.bound}")
    shrink = 1 - a[last] / a[0]
    if shrink < args.shrink:
        failures.append(f"the orbit shrank by {shrink:.3e} of a0 only (at least {args.shrink} wanted)")
    contact = np.nonzero(a <= 2 * radius)[0]
    peters_contact = t[0] + (a[0] ** 4 - (2 * radius) ** 4) / rate
    if contact.size:
        print(f"contact (a = 2 R) at t = {t[contact[0]]:.6g}; Peters: {peters_contact:.6g}")
    else:
        print(f"no contact by t = {t[-1]:.6g}; Peters' contact at t = {peters_contact:.6g}")

    # Frequencies over the same window, from the statistics rows.
    window = released & (rows["time"] >= t[0]) & (rows["time"] <= t[last])
    if np.count_nonzero(window) > 10:
        gw_phase = np.unwrap(np.arctan2(rows["h_cross"][window], rows["h_plus"][window]))
        orbital_phase = np.unwrap(rows["orbital_phase"][window])
        ratio = (gw_phase[-1] - gw_phase[0]) / (2 * (orbital_phase[-1] - orbital_phase[0]))
        print(f"gravitational-wave phase advance / twice the orbital one over t = {t[0]:.6g} .. {t[last]:.6g}: "
              f"{ratio:.6f} ({(orbital_phase[-1] - orbital_phase[0]) / (2 * math.pi):.3f} orbits)")
        if abs(ratio - 1) > args.frequency_bound:
            failures.append(f"GW frequency / twice the orbital frequency = {ratio:.6f}, not within "
                            f"{args.frequency_bound} of 1")
    else:
        failures.append("fewer than 10 statistics rows in the compared window")
    if failures:
        sys.exit("check_peters_inspiral: " + "; ".join(failures))
    print("check_peters_inspiral: passed")


if __name__ == "__main__":
    main()
