#!/usr/bin/python3
"""Plots a Sod shock-tube result (one step of an H5Part file) against the exact Riemann solution.

Writes a PNG with density, velocity, pressure and internal energy against x, and prints the L1
errors of density, pressure and velocity as the app defines them (apps/sod/sod_problem.hh,
measure_l1_errors): the mean absolute error over the fluid particles (kind 0) with
|x - x_interface| < l1_window (the run's value, from the parameters the file holds), against the
exact solution evaluated at each particle's x, summed exactly. Run on the app's last step, the
errors are the ones the app printed (test apps.sod.plot_l1_matches_app). The exact solution comes
from the project's own solver (apps/exact/exact_solution).

    plot_sod.py sod.h5part [--step N] [--output sod.png] [--exact build/apps/exact/exact_solution]
"""
import math
import os
import re
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "plotting"))
import h5part_plot  # noqa: E402

PROGRAM = "plot_sod"


def riemann_arguments(time, gamma, left, right, x0):
    return ["sod", "--t", repr(time), "--gamma", repr(gamma), "--rho-left", repr(left[0]), "--p-left", repr(left[1]),
            "--rho-right", repr(right[0]), "--p-right", repr(right[1]), "--x0", repr(x0)]


def exact_profile(exact, time, gamma, left, right, x0, xmin, xmax):
    """The exact solution on 2000 points of [xmin, xmax], for the figure."""
    return h5part_plot.exact_solution(exact, riemann_arguments(time, gamma, left, right, x0) + [
        "--xmin", repr(xmin), "--xmax", repr(xmax), "--points", "2000"], PROGRAM)


def exact_at(exact, x, time, gamma, left, right, x0):
    """The exact solution at the positions x themselves (exact_solution --x-file), as the app evaluates it."""
    with tempfile.NamedTemporaryFile("w", suffix=".txt") as positions:
        positions.write("".join(repr(float(value)) + "\n" for value in x))
        positions.flush()
        values = h5part_plot.exact_solution(exact, riemann_arguments(time, gamma, left, right, x0) + [
            "--x-file", positions.name], PROGRAM)
    if len(values["x"]) != len(x) or not np.array_equal(values["x"], x):
        sys.exit(f"{PROGRAM}: exact_solution --x-file did not return the {len(x)} positions it was given")
    return values


def run_parameter(attributes, key):
    """A key of the run's resolved parameters (the 'parameters' attribute the apps write), or None."""
    text = attributes.get("parameters")
    if text is None:
        return None
    text = text.decode() if isinstance(text, bytes) else str(text)
    match = re.search(r"^%s\s*=\s*([^\s#]+)" % re.escape(key), text, re.MULTILINE)
    return float(match.group(1)) if match else None


def l1_errors(data, exact, inside):
    """Means of |particle - exact| over `inside`, summed exactly (math.fsum; the app's exact_sum)."""
    count = int(inside.sum())
    return {key: math.fsum(np.abs(data[particle][inside] - exact[key][inside]).tolist()) / count if count else 0.0
            for key, particle in (("rho", "rho"), ("P", "P"), ("v", "vx"))}, count


def main():
    parser = h5part_plot.command_line(__doc__)
    parser.add_argument("--window", type=float,
                        help="L1 errors over |x - x_interface| < window (default: the run's l1_window, else 0.4)")
    args = parser.parse_args()

    time, data, attributes = h5part_plot.read_step(args.file, args.step, PROGRAM)
    number = h5part_plot.number
    gamma = number(attributes, "gamma", 1.4)
    left = (number(attributes, "rho_left", 1.0), number(attributes, "p_left", 1.0))
    right = (number(attributes, "rho_right", 0.125), number(attributes, "p_right", 0.1))
    x0 = number(attributes, "x_interface", 0.0)
    window = args.window if args.window is not None else run_parameter(attributes, "l1_window") or 0.4
    if "kind" in data:  # leave out the fixed wall particles (kind 1) beyond the ends
        fluid = data["kind"] == 0
        data = {k: v[fluid] for k, v in data.items()}
    x = data["x"]
    order = np.argsort(x)
    profile = exact_profile(args.exact, time, gamma, left, right, x0, float(x.min()), float(x.max()))
    inside = np.abs(x - x0) < window
    errors, count = l1_errors(data, exact_at(args.exact, x, time, gamma, left, right, x0), inside)
    # The app's digits (sod.cc, report): 12 significant digits of each error.
    print(f"Sod at t = {time:.4g}: L1 errors over {count} particles with |x - {x0:g}| < {window:g}: "
          f"density {errors['rho']:.11e}, pressure {errors['P']:.11e}, velocity {errors['v']:.11e}")

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
