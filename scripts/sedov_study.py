#!/usr/bin/python3
# Sedov start-up and centre study (issue 13, item 16): for each Sedov run (an H5Part file and the
# statistics file next to it) prints the central pressure ratio (mean P of the particles within
# 0.3 R(t) over the Sedov-Taylor P at the same radii; Kamm & Timmes 2007 through
# apps/exact/exact_solution) and the relative energy change after 10 steps and at the end, and
# draws docs/figures/sedov_study.png: P(r) in shells against the exact profile, and |E(t)/E0 - 1|.
#
#   sedov_study.py --exact build/apps/exact/exact_solution --output docs/figures/sedov_study.png \
#                  LABEL=run.h5part [LABEL=run.h5part ...]
import argparse
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "apps", "plotting"))
import h5part_plot  # noqa: E402

PROGRAM = "sedov_study"
CENTRE = 0.3  # the central region, in units of R(t)


def statistics(path):
    """(time, total energy) columns of a statistics file (columns named in its header)."""
    with open(path) as f:
        names = next(line[1:].split() for line in f if line.startswith("# step "))
    table = np.loadtxt(path, comments="#", ndmin=2)
    return table[:, names.index("time")], table[:, names.index("total")]


def study(path, exact):
    time, data, attributes = h5part_plot.read_step(path, None, PROGRAM)
    number = h5part_plot.number
    dimension = int(number(attributes, "dimension", 3))
    gamma, energy, rho0 = (number(attributes, "gamma", 5 / 3), number(attributes, "blast_energy", 1.0),
                           number(attributes, "rho0", 1.0))
    arguments = ["sedov", "--dim", dimension, "--t", repr(time), "--gamma", repr(gamma), "--energy", repr(energy),
                 "--rho0", repr(rho0)]
    radius = float(h5part_plot.exact_solution(exact, arguments + ["--shock"], PROGRAM)["R"][0])
    profile = h5part_plot.exact_solution(exact, arguments + ["--rmax", repr(1.5 * radius), "--points", "3000"],
                                         PROGRAM)
    r = np.sqrt(sum(data[k] ** 2 for k in ("x", "y", "z")[:dimension]))
    centre = r < CENTRE * radius
    ratio = data["P"][centre].mean() / np.interp(r[centre], profile["r"], profile["P"]).mean()
    t, total = statistics(os.path.splitext(path)[0] + ".statistics.txt")
    change = total / total[0] - 1
    return {"dimension": dimension, "time": time, "radius": radius, "r": r, "P": data["P"], "profile": profile,
            "ratio": ratio, "central_particles": int(centre.sum()), "t": t, "change": change,
            "after_10": change[min(10, len(change) - 1)], "final": change[-1], "steps": len(change) - 1}


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("runs", nargs="+", help="LABEL=file.h5part")
    parser.add_argument("--exact", default=h5part_plot.DEFAULT_EXACT)
    parser.add_argument("--output", help="PNG of the pressure profiles and energy histories")
    args = parser.parse_args()
    results = []
    for run in args.runs:
        label, path = run.split("=", 1)
        result = study(path, args.exact)
        results.append((label, result))
        print(f"{label}: {result['dimension']}D, t = {result['time']:.4g}, {result['steps']} steps: central pressure "
              f"(r < {CENTRE} R, {result['central_particles']} particles) {result['ratio']:.2f} x Sedov-Taylor; "
              f"relative energy change {result['after_10']:.2e} after 10 steps, {result['final']:.2e} at the end")
    if not args.output:
        return
    plt = h5part_plot.pyplot()
    figure, (pressure, energy) = plt.subplots(1, 2, figsize=(13, 4.8))
    for k, (label, result) in enumerate(results):
        colour = f"C{k}"
        style = "-" if k % 3 != 1 else "--"  # the courant runs' profiles lie on the shipped ones
        shells = np.linspace(0, 1.5 * result["radius"], 61)
        which = np.digitize(result["r"], shells)
        centres = [0.5 * (shells[i - 1] + shells[i]) for i in range(1, len(shells)) if np.any(which == i)]
        means = [result["P"][which == i].mean() for i in range(1, len(shells)) if np.any(which == i)]
        pressure.plot(np.array(centres) / result["radius"], means, style, color=colour,
                      label=f"{label} (centre {result['ratio']:.1f}x)")
        pressure.plot(result["profile"]["r"] / result["radius"], result["profile"]["P"], ":", color=colour)
        energy.loglog(result["t"][1:], np.abs(result["change"][1:]) + 1e-16, "-", color=colour, label=label)
    pressure.set_xlabel("r / R(t)")
    pressure.set_ylabel("pressure (shell means; dotted: Sedov-Taylor)")
    pressure.set_xlim(0, 1.25)
    pressure.legend(fontsize=8)
    energy.set_xlabel("t (the first 10 steps end near t = 1e-3)")
    energy.set_ylabel("|E(t) / E(0) - 1|")
    energy.legend(fontsize=8)
    for axis in (pressure, energy):
        axis.grid(alpha=0.3)
    figure.tight_layout()
    figure.savefig(args.output, dpi=110)
    print(f"plot written to {args.output}")


if __name__ == "__main__":
    main()
