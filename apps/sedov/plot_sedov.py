#!/usr/bin/python3
"""Plots a Sedov blast result (one step of an H5Part file) against the Sedov-Taylor solution.

Writes a PNG of density, radial velocity and pressure against the radius (every particle, and the
means in radial shells) with the similarity solution of the project's own solver
(apps/exact/exact_solution sedov; Kamm & Timmes 2007), and prints the radius of the density peak.

    plot_sedov.py sedov_3d.h5part [--step N] [--output sedov.png] [--exact build/apps/exact/exact_solution]
"""
import argparse
import csv
import io
import os
import subprocess
import sys

import h5py
import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
DEFAULT_EXACT = os.path.join(HERE, "..", "..", "build", "apps", "exact", "exact_solution")


def read_step(path, step):
    """Returns (time, {name: array}, root attributes) of one step (the last by default)."""
    with h5py.File(path, "r") as f:
        steps = sorted((k for k in f.keys() if k.startswith("Step#")), key=lambda k: int(k[5:]))
        if not steps:
            sys.exit(f"plot_sedov: {path} holds no Step#N group")
        name = steps[-1] if step is None else f"Step#{step}"
        if name not in f:
            sys.exit(f"plot_sedov: {path} has no {name} (steps: {steps[0]} .. {steps[-1]})")
        group = f[name]
        data = {k: group[k][()] for k in group.keys()}
        time = float(group.attrs.get("TimeValue", group.attrs.get("time", 0.0)))
        attributes = {k: f.attrs[k] for k in f.attrs.keys()}
    return time, data, attributes


def scalar(attributes, key, default):
    value = attributes.get(key, default)
    if hasattr(value, "__len__") and not isinstance(value, (str, bytes)):
        value = value[0]
    return value


def exact_profile(exact, dimension, time, gamma, energy, rho0, rmax):
    command = [exact, "sedov", "--dim", str(dimension), "--t", repr(time), "--gamma", repr(gamma),
               "--energy", repr(energy), "--rho0", repr(rho0), "--rmax", repr(rmax), "--points", "1000"]
    result = subprocess.run(command, capture_output=True, text=True)
    if result.returncode != 0:
        sys.exit(f"plot_sedov: {' '.join(command)} failed: {result.stderr.strip()}")
    rows = list(csv.DictReader(io.StringIO(result.stdout)))
    return {k: np.array([float(r[k]) for r in rows]) for k in rows[0].keys()}


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("file")
    parser.add_argument("--step", type=int)
    parser.add_argument("--output")
    parser.add_argument("--exact", default=DEFAULT_EXACT)
    args = parser.parse_args()

    time, data, attributes = read_step(args.file, args.step)
    dimension = int(scalar(attributes, "dimension", 3))
    gamma = float(scalar(attributes, "gamma", 5.0 / 3.0))
    energy = float(scalar(attributes, "blast_energy", 1.0))
    rho0 = float(scalar(attributes, "rho0", 1.0))
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
    output = args.output or os.path.splitext(args.file)[0] + ".png"
    figure.savefig(output, dpi=110)
    print(f"plot written to {output}")


if __name__ == "__main__":
    main()
