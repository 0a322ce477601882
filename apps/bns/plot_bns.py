#!/usr/bin/python3
"""Plots a bns run: the separation and the strain h+ against time from its statistics file, and
density maps of the orbital plane (column density of the particles within |z| < slab, binned on a
grid) as PNG frames, one per H5Part step.

    plot_bns.py bns_binary.statistics.txt [--output bns_orbit.png]
                [--frames bns_binary.h5part --frame-prefix frames/bns_] [--extent 4] [--slab 0.5]
                [--frame-times 14,22,50]   # only the steps nearest to these times
"""
import argparse
import math
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "plotting"))
import h5part_plot  # noqa: E402

PROGRAM = "plot_bns"


def read_statistics(path):
    """The columns of a statistics file by name (the last header line names them)."""
    names = None
    rows = []
    with open(path) as f:
        for line in f:
            if line.startswith("#"):
                if not line.startswith("# restarted"):
                    names = line[1:].split()
                continue
            if line.strip():
                rows.append([float(x) for x in line.split()])
    if names is None or not rows:
        sys.exit(f"{PROGRAM}: {path} holds no statistics rows")
    data = np.array(rows)
    if data.shape[1] != len(names):
        sys.exit(f"{PROGRAM}: {path}: {data.shape[1]} numbers per row but {len(names)} column names")
    return {name: data[:, k] for k, name in enumerate(names)}


def plot_orbit(columns, output):
    t = columns["time"]
    figure, axes = plt.subplots(2, 1, figsize=(8, 6.5), sharex=True)
    relaxing = columns.get("relaxing", np.zeros_like(t)) > 0.5
    if "separation" in columns:
        axes[0].plot(t, columns["separation"], "k-", lw=1)
        axes[0].set_ylabel("separation")
    else:
        axes[0].plot(t, columns["half_mass_radius"], "k-", lw=1, label="half-mass radius")
        axes[0].plot(t, columns["radius_90"], "b-", lw=1, label="90% radius")
        axes[0].legend()
        axes[0].set_ylabel("radius")
    axes[1].plot(t, columns["h_plus"], "r-", lw=1, label="h+")
    axes[1].plot(t, columns["h_cross"], "b-", lw=0.6, alpha=0.6, label="hx")
    axes[1].set_ylabel("strain at observer_distance")
    axes[1].set_xlabel("t")
    axes[1].legend()
    if relaxing.any():
        release = t[relaxing][-1]
        for axis in axes:
            axis.axvline(release, color="0.6", ls="--", lw=0.8)
        axes[0].set_title(f"relaxation (corotating, damped) until t = {release:.3g}, then free evolution")
    figure.tight_layout()
    figure.savefig(output, dpi=110)
    print(f"{PROGRAM}: wrote {output}")


def plot_frames(path, prefix, extent, slab, bins=100, times=None):
    steps = h5part_plot.step_indices(path, PROGRAM)
    if times:
        # The step nearest to each wanted time (the step attributes hold the times).
        step_times = [h5part_plot.read_step(path, index, PROGRAM)[0] for index in steps]
        steps = sorted({steps[int(np.argmin(np.abs(np.array(step_times) - wanted)))] for wanted in times})
    directory = os.path.dirname(prefix)
    if directory:
        os.makedirs(directory, exist_ok=True)
    edges = np.linspace(-extent, extent, bins + 1)
    area = (edges[1] - edges[0]) ** 2
    written = 0
    for index in steps:
        time, data, _ = h5part_plot.read_step(path, index, PROGRAM)
        x, y, z, m = (data[k] for k in ("x", "y", "z", "m"))
        keep = np.abs(z) < slab
        grid, _, _ = np.histogram2d(x[keep], y[keep], bins=[edges, edges], weights=m[keep])
        # A 3 x 3 binomial filter: a few thousand particles leave single empty cells otherwise.
        weights = np.array([1.0, 2.0, 1.0])
        padded = np.pad(grid, 1)
        grid = sum(weights[i] * weights[j] * padded[i:i + bins, j:j + bins] for i in range(3) for j in range(3)) / 16
        density = grid.T / (area * 2 * slab)
        figure, axis = plt.subplots(figsize=(5.5, 5))
        shown = np.log10(np.maximum(density, 1e-4 * max(density.max(), 1e-300)))
        image = axis.imshow(shown, origin="lower", extent=[-extent, extent, -extent, extent], cmap="inferno")
        figure.colorbar(image, ax=axis, label=f"log10 mean density, |z| < {slab:g}")
        axis.set_xlabel("x")
        axis.set_ylabel("y")
        axis.set_title(f"t = {time:.4g}")
        figure.tight_layout()
        name = f"{prefix}{written:04d}.png"
        figure.savefig(name, dpi=90)
        plt.close(figure)
        written += 1
    print(f"{PROGRAM}: wrote {written} frames {prefix}0000.png ..")


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("statistics", help="the run's statistics file")
    parser.add_argument("--output", default="bns_orbit.png", help="separation and h+ against t")
    parser.add_argument("--frames", help="H5Part output: one density map of the orbital plane per step")
    parser.add_argument("--frame-prefix", default="bns_frame_", help="frames are PREFIX0000.png, ...")
    parser.add_argument("--extent", type=float, default=4.0, help="the maps show |x|, |y| < extent")
    parser.add_argument("--slab", type=float, default=0.5, help="particles with |z| < slab enter the maps")
    parser.add_argument("--frame-times", help="comma-separated times: frames of the nearest steps only")
    args = parser.parse_args()
    columns = read_statistics(args.statistics)
    plot_orbit(columns, args.output)
    if "separation" in columns:
        after = columns.get("relaxing", np.zeros_like(columns["time"])) < 0.5
        if after.any():
            a = columns["separation"][after]
            print(f"{PROGRAM}: after the release: separation {a[0]:.6g} -> {a[-1]:.6g}, "
                  f"largest |a / a0 - 1| = {np.max(np.abs(a / a[0] - 1)):.3e}")
    if args.frames:
        times = [float(v) for v in args.frame_times.split(",")] if args.frame_times else None
        plot_frames(args.frames, args.frame_prefix, args.extent, args.slab, times=times)


if __name__ == "__main__":
    main()
