"""Draws a Kelvin-Helmholtz run: the mode amplitude M(t) (McNally et al. 2012, eqs. 4-7) on a log
scale with the linear-theory slope exp(sigma t) (kh_linear_theory.py) through the fit window's
first point, and the particles coloured by density at the last step (or --step K).

    plot_kelvin_helmholtz.py kh.h5part [--output kh.png] [--window 0.5,1.5] [--step K]
"""
import argparse
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "plotting"))
import h5part_plot  # noqa: E402
import kh_profile  # noqa: E402

PROGRAM = "plot_kelvin_helmholtz"


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("file")
    parser.add_argument("--output", default="kelvin_helmholtz.png")
    parser.add_argument("--window", default="0.5,1.5")
    parser.add_argument("--step", type=int, default=None)
    arguments = parser.parse_args()
    window = tuple(float(v) for v in arguments.window.split(","))

    def read(path, step):
        return h5part_plot.read_step(path, step, PROGRAM)

    times, amplitudes = kh_profile.amplitude_series(arguments.file, read,
                                                    h5part_plot.step_indices(arguments.file, PROGRAM))
    rate = kh_profile.growth_rate(times, amplitudes, window)
    figure, axes = plt.subplots(1, 2, figsize=(12, 5))
    axes[0].semilogy(times, amplitudes, "o-", ms=3, label="SPH (fit %.3f over t in [%g, %g])" % (rate, *window))
    start = np.argmin(np.abs(times - window[0]))
    line = amplitudes[start] * np.exp(kh_profile.LINEAR_GROWTH_RATE * (times - times[start]))
    axes[0].semilogy(times, line, "k--", label="linear theory sigma = %.3f" % kh_profile.LINEAR_GROWTH_RATE)
    axes[0].set_xlabel("t")
    axes[0].set_ylabel("mode amplitude M")
    axes[0].set_ylim(amplitudes.min() / 2, max(amplitudes.max(), 0.05) * 2)
    axes[0].legend()
    time, data, _ = read(arguments.file, arguments.step)
    shown = axes[1].scatter(data["x"] % 1.0, data["y"] % 1.0, c=data["rho"], s=1, cmap="viridis")
    axes[1].set_aspect("equal")
    axes[1].set_title("t = %.3g" % time)
    figure.colorbar(shown, ax=axes[1], label="rho")
    figure.savefig(arguments.output, dpi=110)
    print("%s: %s" % (PROGRAM, arguments.output))


if __name__ == "__main__":
    main()
