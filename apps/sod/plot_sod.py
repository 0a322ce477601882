#!/usr/bin/python3
"""Plots a Sod shock-tube result (one step of an H5Part file) against the exact Riemann solution.

Writes a PNG with density, velocity, pressure and internal energy against x, and prints the L1
errors (mean absolute error over the particles with |x - x0| < 0.4) of density, pressure and
velocity. The exact solution comes from the project's own solver (apps/exact/exact_solution).

    plot_sod.py sod.h5part [--step N] [--output sod.png] [--exact build/apps/exact/exact_solution]
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
            sys.exit(f"plot_sod: {path} holds no Step#N group")
        name = steps[-1] if step is None else f"Step#{step}"
        if name not in f:
            sys.exit(f"plot_sod: {path} has no {name} (steps: {steps[0]} .. {steps[-1]})")
        group = f[name]
        data = {k: group[k][()] for k in group.keys()}
        time = float(group.attrs.get("TimeValue", group.attrs.get("time", 0.0)))
        attributes = {k: f.attrs[k] for k in f.attrs.keys()}
    return time, data, attributes


def exact_profile(exact, time, gamma, left, right, x0, xmin, xmax):
    command = [exact, "sod", "--t", repr(time), "--gamma", repr(gamma),
               "--rho-left", repr(left[0]), "--p-left", repr(left[1]),
               "--rho-right", repr(right[0]), "--p-right", repr(right[1]),
               "--x0", repr(x0), "--xmin", repr(xmin), "--xmax", repr(xmax), "--points", "2000"]
    result = subprocess.run(command, capture_output=True, text=True)
    if result.returncode != 0:
        sys.exit(f"plot_sod: {' '.join(command)} failed: {result.stderr.strip()}")
    rows = list(csv.DictReader(io.StringIO(result.stdout)))
    return {k: np.array([float(r[k]) for r in rows]) for k in rows[0].keys()}


def exact_at(exact, x, time, gamma, left, right, x0):
    """The exact solution sampled at the particle positions (through a dense profile)."""
    profile = exact_profile(exact, time, gamma, left, right, x0, float(x.min()), float(x.max()))
    return {k: np.interp(x, profile["x"], profile[k]) for k in ("rho", "v", "P", "u")}, profile


def attribute(attributes, key, default):
    value = attributes.get(key, default)
    return float(value[0]) if hasattr(value, "__len__") and not isinstance(value, (str, bytes)) else float(value)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("file")
    parser.add_argument("--step", type=int)
    parser.add_argument("--output")
    parser.add_argument("--exact", default=DEFAULT_EXACT)
    parser.add_argument("--window", type=float, default=0.4, help="L1 errors over |x - x0| < window")
    args = parser.parse_args()

    time, data, attributes = read_step(args.file, args.step)
    gamma = attribute(attributes, "gamma", 1.4)
    left = (attribute(attributes, "rho_left", 1.0), attribute(attributes, "p_left", 1.0))
    right = (attribute(attributes, "rho_right", 0.125), attribute(attributes, "p_right", 0.1))
    x0 = attribute(attributes, "x_interface", 0.0)
    if "kind" in data:  # leave out the fixed wall particles (kind 1) beyond the ends
        fluid = data["kind"] == 0
        data = {k: v[fluid] for k, v in data.items()}
    x = data["x"]
    order = np.argsort(x)
    exact, profile = exact_at(args.exact, x, time, gamma, left, right, x0)

    inside = np.abs(x - x0) < args.window
    errors = {
        "rho": np.mean(np.abs(data["rho"][inside] - exact["rho"][inside])),
        "P": np.mean(np.abs(data["P"][inside] - exact["P"][inside])),
        "v": np.mean(np.abs(data["vx"][inside] - exact["v"][inside])),
    }
    print(f"Sod at t = {time:.4g}: L1 errors over {inside.sum()} particles with |x - x0| < {args.window}: "
          f"density {errors['rho']:.3e}, pressure {errors['P']:.3e}, velocity {errors['v']:.3e}")

    figure, axes = plt.subplots(2, 2, figsize=(11, 8), sharex=True)
    panels = [("rho", "rho", "density"), ("vx", "v", "velocity"), ("P", "P", "pressure"),
              ("u", "u", "internal energy")]
    for axis, (particle_key, exact_key, label) in zip(axes.flat, panels):
        axis.plot(x[order], data[particle_key][order], ".", markersize=2, color="#1f77b4", label="FleCSPH-lite")
        axis.plot(profile["x"], profile[exact_key], "-", linewidth=1, color="#d62728", label="exact")
        axis.set_ylabel(label)
        axis.grid(alpha=0.3)
    for axis in axes[1]:
        axis.set_xlabel("x")
    axes[0][0].legend()
    figure.suptitle(f"Sod shock tube, t = {time:.3g}, {len(x)} fluid particles; L1: rho {errors['rho']:.2e}, "
                    f"P {errors['P']:.2e}, v {errors['v']:.2e}")
    figure.tight_layout()
    output = args.output or os.path.splitext(args.file)[0] + ".png"
    figure.savefig(output, dpi=120)
    print(f"plot written to {output}")


if __name__ == "__main__":
    main()
