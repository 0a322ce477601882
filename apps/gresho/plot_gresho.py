#!/usr/bin/python3
"""Plots a Gresho vortex result (one step of an H5Part file): v_phi and P against r (particles,
bin means) with the steady exact state, and prints the binned L1 error of v_phi
(gresho_analysis.py); with alpha in the file (viscosity_switch = on), alpha against r too.

    plot_gresho.py gresho.h5part [--step N] [--output gresho.png]
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "plotting"))
import gresho_analysis  # noqa: E402
import h5part_plot  # noqa: E402


def main():
    args = h5part_plot.command_line(__doc__).parse_args()
    time, data, _ = h5part_plot.read_step(args.file, args.step, "plot_gresho")
    r, v_phi = gresho_analysis.polar(data)
    error = gresho_analysis.l1_error(r, v_phi)
    print("Gresho vortex at t = %.6g, %d particles: binned L1 error of v_phi %.5f" % (time, len(r), error))
    grid = np.linspace(0, 0.5, 500)
    panels = [(v_phi, "v_phi", gresho_analysis.azimuthal_velocity(grid)), (data["P"], "P", gresho_analysis.pressure(grid))]
    if "alpha" in data:
        panels.append((data["alpha"], "alpha", None))
    plt = h5part_plot.pyplot()
    figure, axes = plt.subplots(1, len(panels), figsize=(5 * len(panels), 4.5))
    for axis, (values, label, exact) in zip(axes, panels):
        near = r < 0.5
        axis.plot(r[near], values[near], ".", markersize=1, alpha=0.3, color="#1f77b4", label="particles")
        centres, mean, _ = gresho_analysis.binned(r, values)
        axis.plot(centres, mean, "o-", markersize=3, color="#2ca02c", label="bin means")
        if exact is not None:
            axis.plot(grid, exact, "-", color="#d62728", label="exact")
        axis.set_xlabel("r")
        axis.set_ylabel(label)
        axis.grid(alpha=0.3)
    axes[0].legend()
    figure.suptitle(f"Gresho vortex, t = {time:.3g}, {len(r)} particles: L1(v_phi) = {error:.4f}")
    figure.tight_layout()
    h5part_plot.save(figure, args, dpi=110)


if __name__ == "__main__":
    main()
