#!/usr/bin/python3
"""Plots a Sedov blast result (one step of an H5Part file) against the Sedov-Taylor solution.

Writes a PNG of density, radial velocity and pressure against the radius (every particle, and the
means in radial shells) with the similarity solution of the project's own solver
(apps/exact/exact_solution sedov; Kamm & Timmes 2007), and prints the radius of the density peak.

    plot_sedov.py sedov_3d.h5part [--step N] [--output sedov.png] [--exact build/apps/exact/exact_solution]
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "plotting"))
import h5part_plot  # noqa: E402

PROGRAM = "plot_sedov"


def exact_profile(exact, dimension, time, gamma, energy, rho0, rmax):
    return h5part_plot.exact_solution(exact, [
        "sedov", "--dim", dimension, "--t", repr(time), "--gamma", repr(gamma), "--energy", repr(energy),
        "--rho0", repr(rho0), "--rmax", repr(rmax), "--points", "1000"], PROGRAM)


def main():
    args = h5part_plot.command_line(__doc__).parse_args()

    time, data, attributes = h5part_plot.read_step(args.file, args.step, PROGRAM)
    number = h5part_plot.number
    dimension = int(number(attributes, "dimension", 3))
    gamma = number(attributes, "gamma", 5.0 / 3.0)
    energy = number(attributes, "blast_energy", 1.0)
    rho0 = number(attributes, "rho0", 1.0)
    position = np.stack([data[k] for k in ("x", "y", "z")[:dimension]], axis=1)
    velocity = np.stack([data[k] for k in ("vx", "vy", "vz")[:dimension]], axis=1)
    r = np.linalg.norm(position, axis=1)
    safe = np.where(r > 0, r, 1.0)
    v_r = np.einsum("ij,ij->i", position, velocity) / safe
    profile = exact_profile(args.exact, dimension, time, gamma, energy, rho0, float(r.max()))

    shells = np.linspace(0.0, float(r.max()), 120)
    which = np.digitize(r, shells)
    centres, means = [], {"rho": [], "v": [], "P": []}
    for i in range(1, len(shells)):
        inside = which == i
        if inside.sum() == 0:
            continue
        centres.append(0.5 * (shells[i - 1] + shells[i]))
        means["rho"].append(data["rho"][inside].mean())
        means["v"].append(v_r[inside].mean())
        means["P"].append(data["P"][inside].mean())
    centres = np.array(centres)
    peak = centres[int(np.argmax(means["rho"]))]
    shock = profile["r"][int(np.argmax(profile["rho"]))]
    print(f"Sedov {dimension}D at t = {time:.4g}: density peak at r = {peak:.4f}, Sedov-Taylor shock at "
          f"r = {shock:.4f} ({100 * (peak - shock) / shock:+.1f}%)")

    plt = h5part_plot.pyplot()
    figure, axes = plt.subplots(1, 3, figsize=(15, 4.5))
    panels = [("rho", data["rho"], "density"), ("v", v_r, "radial velocity"), ("P", data["P"], "pressure")]
    for axis, (key, values, label) in zip(axes, panels):
        axis.plot(r, values, ".", markersize=1, alpha=0.3, color="#1f77b4", label="particles")
        axis.plot(centres, means[key], "-", linewidth=1.5, color="#2ca02c", label="shell means")
        axis.plot(profile["r"], profile[key], "-", linewidth=1, color="#d62728", label="Sedov-Taylor")
        axis.set_xlabel("r")
        axis.set_ylabel(label)
        axis.grid(alpha=0.3)
    axes[0].legend()
    figure.suptitle(f"Sedov blast {dimension}D, t = {time:.3g}, {len(r)} particles; density peak r = {peak:.3f}, "
                    f"exact shock r = {shock:.3f}")
    figure.tight_layout()
    h5part_plot.save(figure, args, dpi=110)


if __name__ == "__main__":
    main()
