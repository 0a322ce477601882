"""Draws a Rayleigh-Taylor run: the mode amplitude A(t) (rt_profile.py) on a log scale with the
linear-theory rates (rt_linear_theory.py: smooth profile compressible and incompressible, sharp
interface) through the fit window's first point, and the particles coloured by density at a few
times (walls grey).

    plot_rayleigh_taylor.py rt.h5part [--output rt.png] [--window 0.8,2.0] [--times 0,1,2,3]
"""
import argparse
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "plotting"))
import h5part_plot  # noqa: E402
import rt_linear_theory  # noqa: E402
import rt_profile  # noqa: E402

PROGRAM = "plot_rayleigh_taylor"


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("file")
    parser.add_argument("--output", default="rayleigh_taylor.png")
    parser.add_argument("--window", default="0.8,2.0")
    parser.add_argument("--times", default=None, help="times of the density frames (default: 4 spread over the run)")
    arguments = parser.parse_args()
    window = tuple(float(v) for v in arguments.window.split(","))
    setup = rt_profile.SetUp(h5part_plot.attributes(arguments.file, PROGRAM))
    steps = h5part_plot.step_indices(arguments.file, PROGRAM)

    def read(path, step):
        return h5part_plot.read_step(path, step, PROGRAM)

    times, amplitudes = rt_profile.amplitude_series(arguments.file, read, steps, setup)
    rate = rt_profile.growth_rate_two_modes(times, amplitudes, window)
    theory = rt_linear_theory.rates(setup)
    wanted = ([float(t) for t in arguments.times.split(",")] if arguments.times else
              list(np.linspace(times[0], times[-1], 4)))
    frames = [steps[int(np.argmin(np.abs(times - t)))] for t in wanted]
    figure, axes = plt.subplots(1, 1 + len(frames), figsize=(4.5 + 2.6 * len(frames), 5),
                                gridspec_kw={"width_ratios": [2.2] + [1] * len(frames)})
    axes[0].semilogy(times, amplitudes, "o-", ms=3, label="SPH (two-mode fit %.3f over t in [%g, %g])" % (rate, *window))
    start = int(np.argmin(np.abs(times - window[0])))
    for name, style in (("smooth_compressible", "k--"), ("smooth_incompressible", "k:"),
                        ("sharp_incompressible", "r-.")):
        line = amplitudes[start] * np.exp(theory[name] * (times - times[start]))
        axes[0].semilogy(times, line, style, label="%s sigma = %.3f" % (name.replace("_", " "), theory[name]))
    axes[0].set_xlabel("t")
    axes[0].set_ylabel("mode amplitude A of v_y")
    axes[0].set_ylim(amplitudes.min() / 2, amplitudes.max() * 3)
    axes[0].legend(fontsize=8)
    for axis, step in zip(axes[1:], frames):
        time, data, _ = read(arguments.file, step)
        fluid = data["kind"] == 0
        axis.scatter(data["x"][~fluid], data["y"][~fluid], c="0.7", s=0.5)
        shown = axis.scatter(data["x"][fluid], data["y"][fluid], c=data["rho"][fluid], s=0.5, cmap="viridis",
                             vmin=setup.rho1 * 0.9, vmax=setup.rho2 * 1.05)
        axis.set_aspect("equal")
        axis.set_xlim(0, setup.width)
        axis.set_title("t = %.3g" % time)
        axis.set_xticks([0, setup.width])
    figure.colorbar(shown, ax=axes[1:], label="rho", shrink=0.8)
    figure.savefig(arguments.output, dpi=110)
    print("%s: %s" % (PROGRAM, arguments.output))


if __name__ == "__main__":
    main()
