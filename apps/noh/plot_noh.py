#!/usr/bin/python3
"""Plots a Noh implosion result (one step of an H5Part file) against the exact solution.

Density, radial velocity and internal energy against the radius (every particle, and the means
in shells) with the exact solution (noh_analysis.py), and prints the measures of check_noh.py:
the shock radius, the post-shock density and the wall heating.

    plot_noh.py noh_2d.h5part [--step N] [--output noh.png]
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "plotting"))
import h5part_plot  # noqa: E402
import noh_analysis  # noqa: E402

PROGRAM = "plot_noh"


def main():
    args = h5part_plot.command_line(__doc__).parse_args()
    time, data, attributes = h5part_plot.read_step(args.file, args.step, PROGRAM)
    number = h5part_plot.number
    dimension = int(number(attributes, "dimension", 2))
    gamma = number(attributes, "gamma", 5.0 / 3.0)
    rho0 = number(attributes, "rho0", 1.0)
    speed = number(attributes, "inflow_speed", 1.0)
    r, v_r = noh_analysis.radii(data, dimension)
    m = noh_analysis.measure(r, data["rho"], data["u"], time, dimension, gamma, rho0, speed)
    print(noh_analysis.summary(m, dimension))
    rmax = 2.5 * m["exact_shock_radius"]
    near = r < rmax
    grid = np.linspace(1e-4, rmax, 600)
    exact = noh_analysis.exact(grid, time, dimension, gamma, rho0, speed)
    plt = h5part_plot.pyplot()
    figure, axes = plt.subplots(1, 3, figsize=(15, 4.5))
    panels = [(data["rho"], "density"), (v_r, "radial velocity"), (data["u"], "internal energy")]
    for axis, (values, label), reference in zip(axes, panels, exact):
        axis.plot(r[near], values[near], ".", markersize=1, alpha=0.3, color="#1f77b4", label="particles")
        centres, means, _ = noh_analysis.shell_means(r[near], values[near], rmax / 100, 100)
        axis.plot(centres, means, "-", linewidth=1.5, color="#2ca02c", label="shell means")
        axis.plot(grid, reference, "-", linewidth=1, color="#d62728", label="exact (Noh 1987)")
        axis.set_xlabel("r")
        axis.set_ylabel(label)
        axis.grid(alpha=0.3)
    axes[0].legend()
    figure.suptitle(f"Noh {dimension}D, t = {time:.3g}, {len(r)} particles: shock r = {m['shock_radius']:.4f} "
                    f"(exact {m['exact_shock_radius']:.4f}), post-shock density {m['plateau_density']:.3f} "
                    f"(exact {m['exact_density']:.3g})")
    figure.tight_layout()
    h5part_plot.save(figure, args, dpi=110)


if __name__ == "__main__":
    main()
