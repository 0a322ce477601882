#!/usr/bin/python3
"""Draws a bns inspiral with radiation reaction from its statistics file (docs/bns.md).

Four panels against time (in ms when the run is in physical units, unit_time_in_cgs = 1e-3; in code
units otherwise): the separation of the stars' centres of mass with Peters' (1964) circular
inspiral from the release, a(t)^4 = a0^4 - (256/5) G^3 m1 m2 M (t - t0) / c^5, and the separations
3 R and 2 R (contact); the energies (E - E0, minus the radiated energy, and the balance E +
E_radiated - its start); the strain h+, hx at observer_distance; the gravitational-wave frequency
(the time derivative of the unwrapped phase of h+ + i hx over 2 pi) against twice the orbital
frequency and Peters' 2 f_orb of a(t). G and c are the run's: from the unit keys with
physical_constants = true, else gravitational_constant and speed_of_light.

    plot_inspiral.py bns_inspiral.statistics.txt --output bns_inspiral.png
"""
import argparse
import math
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402


def read(path):
    parameters, names, rows = {}, None, []
    with open(path) as f:
        for line in f:
            if line.startswith("#   ") and "=" in line:
                key, value = line[4:].split("#")[0].split("=", 1)
                parameters[key.strip()] = value.strip().strip('"')
            elif line.startswith("# step "):
                names = line[1:].split()
            elif not line.startswith("#") and line.strip():
                rows.append([float(v) for v in line.split()])
    if names is None or not rows:
        sys.exit(f"plot_inspiral: '{path}' holds no column line or no rows")
    table = np.array(rows)
    return parameters, {name: table[:, i] for i, name in enumerate(names)}


def constants(p):
    """G and c of the run (bns_problem.cc: physical_constants_in_code_units)."""
    if p.get("physical_constants") == "true":
        mass, length, time = (float(p[k]) for k in ("unit_mass_in_cgs", "unit_length_in_cgs", "unit_time_in_cgs"))
        return 6.67430e-8 * mass * time**2 / length**3, 2.99792458e10 * time / length
    return float(p.get("gravitational_constant", 1)), float(p.get("speed_of_light", 1))


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("statistics")
    parser.add_argument("--output", default="bns_inspiral.png")
    args = parser.parse_args()
    p, s = read(args.statistics)
    if "radiated_energy" not in s:
        sys.exit("plot_inspiral: no radiated_energy column (run with radiation_reaction = true)")
    G, c = constants(p)
    m1, m2, radius = float(p["star_mass"]), float(p["companion_mass"]), float(p["star_radius"])
    in_ms = p.get("physical_constants") == "true" and float(p.get("unit_time_in_cgs", 1)) == 1e-3
    time_label = "t [ms]" if in_ms else "t [code units]"
    length_label = " [km]" if in_ms and float(p.get("unit_length_in_cgs", 1)) == 1e5 else ""
    t = s["time"]
    released = s["relaxing"] == 0
    t0 = t[np.argmax(released)]
    a0 = s["separation"][np.argmax(released)]
    rate = 256.0 / 5.0 * G**3 * m1 * m2 * (m1 + m2) / c**5
    after = released
    peters = np.maximum(a0**4 - rate * (t[after] - t0), 0.0) ** 0.25

    figure, axes = plt.subplots(4, 1, figsize=(8, 13), sharex=True)
    ax = axes[0]
    ax.plot(t, s["separation"], label="SPH: centres of mass")
    ax.plot(t[after], peters, "--", label="Peters (1964) from the release")
    for multiple, style in ((3, ":"), (2, "-.")):
        ax.axhline(multiple * radius, color="grey", linestyle=style, linewidth=0.8)
    ax.set_ylabel("separation" + length_label)
    ax.legend()
    ax.set_title(f"m1 = {m1}, m2 = {m2}, R = {radius}, G = {G:.6g}, c = {c:.6g}")

    ax = axes[1]
    e0 = s["total"][np.argmax(released)]
    balance0 = s["energy_balance"][np.argmax(released)]
    ax.plot(t[after], s["total"][after] - e0, label="E - E(release)")
    ax.plot(t[after], -s["radiated_energy"][after] + s["radiated_energy"][np.argmax(released)],
            "--", label="- radiated energy")
    ax.plot(t[after], s["energy_balance"][after] - balance0, label="E + E_radiated - its value at release")
    ax.set_ylabel("energy [code units]")
    ax.legend()

    ax = axes[2]
    ax.plot(t, s["h_plus"], label="h+")
    ax.plot(t, s["h_cross"], label="hx", alpha=0.7)
    ax.set_ylabel(f"strain at d = {float(p['observer_distance']):.4g}")
    ax.legend()

    ax = axes[3]
    phase = np.unwrap(np.arctan2(s["h_cross"][after], s["h_plus"][after]))
    orbit = np.unwrap(s["orbital_phase"][after])
    scale = 1e3 if in_ms else 1.0  # Hz from 1/ms
    ax.plot(t[after], np.gradient(phase, t[after]) / (2 * math.pi) * scale, label="f_GW (strain phase)")
    ax.plot(t[after], 2 * np.gradient(orbit, t[after]) / (2 * math.pi) * scale, "--", label="2 f_orb (centres)")
    kepler = np.sqrt(G * (m1 + m2) / np.maximum(peters, 1e-30) ** 3)
    ax.plot(t[after], 2 * kepler / (2 * math.pi) * scale, ":", label="2 f_orb of Peters' a(t)")
    ax.set_ylabel("frequency [Hz]" if in_ms else "frequency")
    top = 2 * math.sqrt(G * (m1 + m2) / (1.5 * radius) ** 3) / (2 * math.pi) * scale
    ax.set_ylim(0, top)
    ax.set_xlabel(time_label)
    ax.legend()
    figure.tight_layout()
    figure.savefig(args.output, dpi=90)
    print(f"plot_inspiral: wrote {args.output}")


if __name__ == "__main__":
    main()
