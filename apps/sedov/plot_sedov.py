#!/usr/bin/python3
"""Plots a Sedov blast result (one step of an H5Part file) against the Sedov-Taylor solution.

Writes a PNG of density, radial velocity and pressure against the radius (every particle, and the
means in radial shells) with the similarity solution of the project's own solver
(apps/exact/exact_solution sedov; Kamm & Timmes 2007), and prints the app's comparison
(apps/sedov/sedov_problem.hh, compare_with_sedov_taylor): the mean density in 128 shells of width
1.5 R(t) / 128, the shell of the highest mean (the density peak), the shock front where the means
fall to half height outside the peak, against the Sedov-Taylor radius R(t). Run on the app's last
step, the numbers are the ones the app printed (test apps.sedov.plot_matches_app).

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


SHELL_COUNT = 128  # sedov_problem.hh: shell_count


def compare_with_sedov_taylor(r, rho, shock_radius, rho0):
    """The app's shock comparison (compare_with_sedov_taylor): (front, peak radius, peak density)."""
    width = 1.5 * shock_radius / SHELL_COUNT
    shell = np.floor(r / width)
    keep = shell < SHELL_COUNT
    shell = shell[keep].astype(int)
    sums = np.bincount(shell, weights=rho[keep], minlength=SHELL_COUNT)
    count = np.bincount(shell, minlength=SHELL_COUNT)
    mean = np.where(count > 0, sums / np.maximum(count, 1), 0.0)
    peak, peak_density = -1, 0.0
    for i in range(SHELL_COUNT):  # the first shell of the highest mean, as the app's strict '>'
        if count[i] >= 1 and mean[i] > peak_density:
            peak, peak_density = i, mean[i]
    half = 0.5 * (peak_density + rho0)
    front = 0.0
    for i in range(max(peak, 0), SHELL_COUNT - 1):
        if count[i + 1] < 1 or mean[i + 1] > half:
            continue
        front = (i + 0.5 + (mean[i] - half) / (mean[i] - mean[i + 1])) * width
        break
    return front, (peak + 0.5) * width, peak_density


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
    r2 = position[:, 0] * position[:, 0]
    for k in range(1, dimension):  # summed in the app's order
        r2 = r2 + position[:, k] * position[:, k]
    r = np.sqrt(r2)
    safe = np.where(r > 0, r, 1.0)
    v_r = np.einsum("ij,ij->i", position, velocity) / safe
    profile = exact_profile(args.exact, dimension, time, gamma, energy, rho0, float(r.max()))
    shock = h5part_plot.exact_solution(args.exact, [
        "sedov", "--dim", dimension, "--t", repr(time), "--gamma", repr(gamma), "--energy", repr(energy),
        "--rho0", repr(rho0), "--shock"], PROGRAM)
    shock_radius, analytic_peak = float(shock["R"][0]), float(shock["rho"][0])
    front, peak, peak_density = compare_with_sedov_taylor(r, data["rho"], shock_radius, rho0)
    # The app's line (sedov.cc, report), 12 significant digits.
    print(f"Sedov {dimension}D at t = {time:.12g}: density peak at r = {peak:.12g}, Sedov-Taylor shock at "
          f"r = {shock_radius:.12g}, shock front (half height) at r = {front:.12g}, relative difference "
          f"{(front - shock_radius) / shock_radius:.12g}; mean density at the peak {peak_density:.12g} "
          f"(strong shock {analytic_peak:.12g})")

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
    figure.suptitle(f"Sedov blast {dimension}D, t = {time:.3g}, {len(r)} particles; shock front r = {front:.3f}, "
                    f"density peak r = {peak:.3f}, exact shock r = {shock_radius:.3f}")
    figure.tight_layout()
    h5part_plot.save(figure, args, dpi=110)


if __name__ == "__main__":
    main()
