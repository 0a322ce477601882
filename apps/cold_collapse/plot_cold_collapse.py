#!/usr/bin/python3
"""Plots the cold collapse of a uniform sphere against free fall.

For every H5Part step: the radii holding 50%, 90% and 99% of the mass (and the app's radius_mass_fraction),
each divided by its value at t = 0, against t / t_ff, with the free-fall curve x(t) of
t / t_ff = (2 / pi) (arccos(sqrt(x)) + sqrt(x (1 - x))) that every shell of a uniform sphere follows.
Prints the largest |r / r_free_fall - 1| of each fraction up to --until t_ff.

    plot_cold_collapse.py cold_collapse.h5part [--output cold_collapse.png] [--until 0.9]
"""
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "plotting"))
import h5part_plot  # noqa: E402

PROGRAM = "plot_cold_collapse"


def free_fall_time_of(tau):
    return lambda x: 2.0 / math.pi * (math.acos(math.sqrt(x)) + math.sqrt(x * (1.0 - x))) - tau


def free_fall_radius(tau):
    """x = r / r0 at tau = t / t_ff (bisection)."""
    if tau <= 0:
        return 1.0
    if tau >= 1:
        return 0.0
    f, lo, hi = free_fall_time_of(tau), 0.0, 1.0
    for _ in range(100):
        mid = 0.5 * (lo + hi)
        lo, hi = (mid, hi) if f(mid) > 0 else (lo, mid)
    return 0.5 * (lo + hi)


def fraction_radius(radius, mass, fraction):
    order = np.argsort(radius)
    cumulative = np.cumsum(mass[order])
    return float(np.interp(fraction * cumulative[-1], cumulative, radius[order]))


def main():
    parser = h5part_plot.command_line(__doc__)
    parser.add_argument("--until", type=float, default=0.9, help="errors up to this fraction of t_ff")
    args = parser.parse_args()
    indices = h5part_plot.step_indices(args.file, PROGRAM)
    attributes = h5part_plot.attributes(args.file, PROGRAM)
    radius_of_sphere = h5part_plot.number(attributes, "sphere_radius", 1.0)
    mass_of_sphere = h5part_plot.number(attributes, "sphere_mass", 1.0)
    gravitational_constant = h5part_plot.number(attributes, "gravitational_constant", 1.0)
    app_fraction = h5part_plot.number(attributes, "radius_mass_fraction", 0.9)
    t_ff = 0.5 * math.pi * math.sqrt(radius_of_sphere ** 3 / (2.0 * gravitational_constant * mass_of_sphere))
    fractions = sorted({0.5, 0.9, 0.99, app_fraction})

    times, radii, counts = [], [], []
    for k in indices:
        time, data, _ = h5part_plot.read_step(args.file, k, PROGRAM)
        counts.append(len(data["x"]))
        r = np.sqrt(data["x"] ** 2 + data["y"] ** 2 + data["z"] ** 2)
        times.append(time)
        radii.append([fraction_radius(r, data["m"], f) for f in fractions])
    times, radii = np.array(times), np.array(radii)
    order = np.argsort(times)
    times, radii = times[order], radii[order]
    tau = times / t_ff
    expected = np.array([free_fall_radius(t) for t in tau])

    plt = h5part_plot.pyplot()
    figure, (axis, errors) = plt.subplots(2, 1, figsize=(8, 8), sharex=True, gridspec_kw={"height_ratios": [3, 1]})
    curve = np.linspace(0, 1, 400)
    axis.plot(curve, [free_fall_radius(t) for t in curve], "k-", linewidth=1, label="free fall")
    compared = tau <= args.until * (1 + 1e-9)
    for j, f in enumerate(fractions):
        ratio = radii[:, j] / radii[0, j]
        worst = np.max(np.abs(ratio[compared] / expected[compared] - 1)) if compared.any() else float("nan")
        print(f"cold collapse: radius of {f:g} of the mass: r0 = {radii[0, j]:.5f}, largest |r / r_free_fall - 1| "
              f"up to {args.until} t_ff = {worst:.4f}")
        axis.plot(tau, ratio, "o-", markersize=3, linewidth=0.8, label=f"r({f:g} M) / r0: max error {worst:.2%}")
        errors.plot(tau[compared], ratio[compared] / expected[compared] - 1, "o-", markersize=3, linewidth=0.8)
    axis.axvline(args.until, color="grey", linestyle=":", linewidth=1)
    axis.set_ylabel("r / r(t = 0)")
    axis.grid(alpha=0.3)
    axis.legend(fontsize=8)
    errors.axhline(0, color="k", linewidth=0.5)
    errors.set_xlabel("t / t_ff")
    errors.set_ylabel("r / r_free_fall - 1")
    errors.grid(alpha=0.3)
    axis.set_title(f"Cold collapse of a uniform sphere, {counts[0]} particles, t_ff = {t_ff:.4f}")
    figure.tight_layout()
    h5part_plot.save(figure, args, dpi=120)


if __name__ == "__main__":
    main()
