#!/usr/bin/python3
"""Plots a Sod shock-tube result (one step of an H5Part file) against the exact Riemann solution.

Writes a PNG with density, velocity, pressure and internal energy against x, and prints the L1
errors (mean absolute error over the particles with |x - x0| < 0.4) of density, pressure and
velocity. The exact solution comes from the project's own solver (apps/exact/exact_solution).

    plot_sod.py sod.h5part [--step N] [--output sod.png] [--exact build/apps/exact/exact_solution]
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "plotting"))
import h5part_plot  # noqa: E402

PROGRAM = "plot_sod"


def exact_profile(exact, time, gamma, left, right, x0, xmin, xmax):
    return h5part_plot.exact_solution(exact, [
        "sod", "--t", repr(time), "--gamma", repr(gamma), "--rho-left", repr(left[0]), "--p-left", repr(left[1]),
        "--rho-right", repr(right[0]), "--p-right", repr(right[1]), "--x0", repr(x0), "--xmin", repr(xmin),
        "--xmax", repr(xmax), "--points", "2000"], PROGRAM)


def exact_at(exact, x, time, gamma, left, right, x0):
    """The exact solution sampled at the particle positions (through a dense profile)."""
    profile = exact_profile(exact, time, gamma, left, right, x0, float(x.min()), float(x.max()))
    return {k: np.interp(x, profile["x"], profile[k]) for k in ("rho", "v", "P", "u")}, profile


def main():
    parser = h5part_plot.command_line(__doc__)
    parser.add_argument("--window", type=float, default=0.4, help="L1 errors over |x - x0| < window")
    args = parser.parse_args()

    time, data, attributes = h5part_plot.read_step(args.file, args.step, PROGRAM)
    number = h5part_plot.number
    gamma = number(attributes, "gamma", 1.4)
    left = (number(attributes, "rho_left", 1.0), number(attributes, "p_left", 1.0))
    right = (number(attributes, "rho_right", 0.125), number(attributes, "p_right", 0.1))
    x0 = number(attributes, "x_interface", 0.0)
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

    plt = h5part_plot.pyplot()
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
    h5part_plot.save(figure, args, dpi=120)


if __name__ == "__main__":
    main()
