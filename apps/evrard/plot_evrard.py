#!/usr/bin/python3
"""Plots an Evrard collapse run against the 1D Lagrangian reference (evrard_reference.py).

Two PNGs: the energies K, U, W and E = K + U + W against t from the run's statistics file, with the
reference's curves; and the radial profiles (density, radial velocity, pressure, entropy A = P / rho^gamma)
of the H5Part step nearest to --time (default 0.8) against the reference profile at that step's time (the
stored 1000-shell profile at t = 0.8 exactly, else the solver run to that time with 500 shells). Prints the
largest |E - E0| / |E0| and the L1 differences of log rho and of v_r in radial bins.

    plot_evrard.py evrard.h5part [--statistics evrard.statistics.txt] [--time 0.8] \\
        [--energies-output evrard_energies.png] [--output evrard_profiles.png] [--no-profiles]
"""
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "plotting"))
import h5part_plot  # noqa: E402

PROGRAM = "plot_evrard"
REFERENCE_PROFILE = os.path.join(HERE, "evrard_reference_t0.8.txt")
REFERENCE_ENERGIES = os.path.join(HERE, "evrard_reference_energies.txt")
REFERENCE_SHELLS = 500  # for a profile at another time than the data file's
POTENTIAL_NAMES = ("potential", "gravitational", "potential_energy", "gravitational_energy")


def read_statistics(path):
    """{column name: array} of a statistics file (the column line is the header's last line)."""
    column_line = None
    with open(path) as f:
        for line in f:
            if not line.startswith("#"):
                break
            column_line = line
    if column_line is None:
        sys.exit(f"{PROGRAM}: {path} has no header")
    names = column_line[1:].split()
    data = np.atleast_2d(np.loadtxt(path))
    if data.shape[1] != len(names):
        sys.exit(f"{PROGRAM}: {path}: {data.shape[1]} columns but the column line names {len(names)}")
    return {name: data[:, k] for k, name in enumerate(names)}


def energies_of(statistics):
    """t, K, U, W, E; W from its column, or E - K - U - walls where the file has none."""
    t, kinetic, internal, total = (statistics[k] for k in ("time", "kinetic", "internal", "total"))
    for name in POTENTIAL_NAMES:
        if name in statistics:
            return t, kinetic, internal, statistics[name], total
    return t, kinetic, internal, total - kinetic - internal - statistics.get("walls", 0.0), total


def step_nearest(path, time):
    """The index k of the Step#k whose time is nearest to `time` (the lower k of a tie)."""
    times = h5part_plot.step_times(path, PROGRAM)
    return min(sorted(times), key=lambda k: abs(times[k] - time))


def plot_energies(plt, statistics_path, output):
    t, kinetic, internal, potential, total = energies_of(read_statistics(statistics_path))
    error = np.max(np.abs(total - total[0])) / abs(total[0])
    print(f"Evrard energies from {statistics_path}: E0 = {total[0]:.6f}, at t = {t[-1]:.4g} E = {total[-1]:.6f}; "
          f"largest |E - E0| / |E0| = {error:.3e}")
    reference = np.loadtxt(REFERENCE_ENERGIES)
    figure, axis = plt.subplots(figsize=(8, 5.5))
    for values, column, label, colour in ((kinetic, 1, "K", "#1f77b4"), (internal, 2, "U", "#d62728"),
                                          (potential, 3, "W", "#2ca02c"), (total, 4, "E = K + U + W", "k")):
        axis.plot(t, values, "-", color=colour, linewidth=1.5, label=f"{label} (SPH)")
        axis.plot(reference[:, 0], reference[:, column], "--", color=colour, linewidth=1, label=f"{label} (1D reference)")
    axis.set_xlim(0, max(t[-1], 0.1))
    axis.set_xlabel("t")
    axis.set_ylabel("energy")
    axis.grid(alpha=0.3)
    axis.legend(ncol=2, fontsize=8)
    axis.set_title(f"Evrard collapse: energies; largest |E - E0| / |E0| = {error:.2e}")
    figure.tight_layout()
    figure.savefig(output, dpi=120)
    print(f"plot written to {output}")
    return error


def reference_profile_at(time):
    """The 1D reference's profile at `time` (evrard_reference.solve; a few seconds)."""
    sys.path.insert(0, HERE)
    import evrard_reference  # noqa: E402

    profile, _, _ = evrard_reference.solve(REFERENCE_SHELLS, time, time, time, 0.25, 2.0, 0.1)
    return profile


def binned(radius, values, edges):
    index = np.digitize(radius, edges) - 1
    means = np.full(len(edges) - 1, np.nan)
    for b in range(len(edges) - 1):
        chosen = index == b
        if chosen.sum() >= 3:
            means[b] = np.mean(values[chosen])
    return means


def plot_profiles(plt, args):
    step = args.step if args.step is not None else step_nearest(args.file, args.time)
    time, data, attributes = h5part_plot.read_step(args.file, step, PROGRAM)
    gamma = h5part_plot.number(attributes, "gamma", 5.0 / 3.0)
    x, y, z = data["x"], data["y"], data["z"]
    radius = np.sqrt(x * x + y * y + z * z)
    radial_velocity = (x * data["vx"] + y * data["vy"] + z * data["vz"]) / np.maximum(radius, 1e-300)
    entropy = data["P"] / data["rho"] ** gamma
    if abs(time - 0.8) <= 1e-6:
        reference = np.loadtxt(REFERENCE_PROFILE)
        source = "evrard_reference_t0.8.txt (1000 shells)"
    else:  # the app's outputs fall on the first step past each output time: solve to that time
        reference = reference_profile_at(time)
        source = f"evrard_reference.py, {REFERENCE_SHELLS} shells, solved to t = {time:.4g}"

    edges = np.logspace(-2, 0, 41)
    centres = np.sqrt(edges[1:] * edges[:-1])
    particle_rho = binned(radius, data["rho"], edges)
    particle_v = binned(radius, radial_velocity, edges)
    reference_rho = np.interp(centres, reference[:, 0], reference[:, 1])
    reference_v = np.interp(centres, reference[:, 0], reference[:, 2])
    valid = np.isfinite(particle_rho) & (centres < reference[-1, 0])
    l1_log_rho = np.mean(np.abs(np.log10(particle_rho[valid]) - np.log10(reference_rho[valid])))
    l1_v = np.mean(np.abs(particle_v[valid] - reference_v[valid]))
    print(f"Evrard profiles at t = {time:.4g} ({len(radius)} particles): mean over {valid.sum()} log-spaced radial "
          f"bins in [0.01, 1] of |log10 rho - log10 rho_ref| = {l1_log_rho:.3f}, of |v_r - v_ref| = {l1_v:.3f}")

    figure, axes = plt.subplots(2, 2, figsize=(11, 8), sharex=True)
    panels = [(data["rho"], 1, "density", True), (radial_velocity, 2, "radial velocity", False),
              (data["P"], 3, "pressure", True), (entropy, 5, "entropy A = P / rho^gamma", False)]
    for axis, (values, column, label, logarithmic) in zip(axes.flat, panels):
        axis.plot(radius, values, ".", markersize=1, color="#1f77b4", alpha=0.4, label="SPH particles")
        axis.plot(centres, binned(radius, values, edges), "o", markersize=3, color="#ff7f0e", label="SPH, binned")
        axis.plot(reference[:, 0], reference[:, column], "-", linewidth=1, color="#d62728", label="1D reference")
        axis.set_xscale("log")
        if logarithmic:
            axis.set_yscale("log")
        axis.set_ylabel(label)
        axis.grid(alpha=0.3)
    axes[1][1].set_ylim(0, 0.3)
    for axis in axes[1]:
        axis.set_xlabel("r")
        axis.set_xlim(1e-2, 1.5)
    axes[0][0].legend(fontsize=8)
    figure.suptitle(f"Evrard collapse at t = {time:.4g}, {len(radius)} particles; 1D reference: {source}", fontsize=10)
    figure.tight_layout()
    h5part_plot.save(figure, args, dpi=120)
    return l1_log_rho, l1_v


def main():
    parser = h5part_plot.command_line(__doc__)
    parser.add_argument("--statistics", help="the run's statistics file (default: <file stem>.statistics.txt)")
    parser.add_argument("--time", type=float, default=0.8, help="profiles of the step nearest to this time")
    parser.add_argument("--energies-output", help="energy PNG (default: <file stem>_energies.png)")
    parser.add_argument("--no-profiles", action="store_true", help="only the energy plot")
    args = parser.parse_args()
    stem = os.path.splitext(args.file)[0]
    plt = h5part_plot.pyplot()
    plot_energies(plt, args.statistics or stem + ".statistics.txt", args.energies_output or stem + "_energies.png")
    if not args.no_profiles:
        if args.output is None:
            args.output = stem + "_profiles.png"
        plot_profiles(plt, args)


if __name__ == "__main__":
    main()
