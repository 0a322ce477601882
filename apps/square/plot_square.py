"""Draws the square test: the particles coloured by density at the first and the last step (or
--step K), with the original square's outline, and prints check_square.py's measures. --corner
shows the lower left corner only, with its corner box (square_analysis.corner_cover).

    plot_square.py square.h5part [--output square.png] [--step K] [--corner]
"""
import argparse
import os
import sys

import matplotlib

matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "plotting"))
import h5part_plot  # noqa: E402
import square_analysis  # noqa: E402

PROGRAM = "plot_square"


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("file")
    parser.add_argument("--output", default="square.png")
    parser.add_argument("--step", type=int, default=None)
    parser.add_argument("--corner", action="store_true", help="the lower left corner and its corner box only")
    arguments = parser.parse_args()
    attributes = h5part_plot.attributes(arguments.file, PROGRAM)
    steps = h5part_plot.step_indices(arguments.file, PROGRAM)
    _, first, _ = h5part_plot.read_step(arguments.file, steps[0], PROGRAM)
    time, now, _ = h5part_plot.read_step(arguments.file, arguments.step, PROGRAM)
    result = square_analysis.measures(first, now, int(h5part_plot.number(attributes, "square_first_id", 0)))
    figure, axes = plt.subplots(1, 2, figsize=(11, 5.2))
    for axis, (t, data) in zip(axes, ((0.0, first), (time, now))):
        shown = axis.scatter(data["x"] % 1.0, data["y"] % 1.0, c=data["rho"], s=8 if arguments.corner else 2, cmap="viridis", vmin=1, vmax=4.2)
        axis.plot([0.25, 0.75, 0.75, 0.25, 0.25], [0.25, 0.25, 0.75, 0.75, 0.25], "r-", lw=0.6)
        axis.set_aspect("equal")
        if arguments.corner:
            box = 0.25 + square_analysis.CORNER
            axis.plot([0.25, box, box, 0.25, 0.25], [0.25, 0.25, box, box, 0.25], "k-", lw=0.8)
            axis.set_xlim(0.2, 0.36)
            axis.set_ylim(0.2, 0.36)
        else:
            axis.set_xlim(0, 1)
            axis.set_ylim(0, 1)
        axis.set_title("t = %.3g" % t)
    figure.colorbar(shown, ax=axes, label="rho")
    figure.suptitle("square test: squareness %.2f (square 1, circle 0), corner cover %.2f (circle %.2f), dense fraction %.2f" %
                    (result["squareness"], result["corner_cover"], result["circle_corner_cover"], result["dense_fraction"]))
    figure.savefig(arguments.output, dpi=110)
    print("%s: %s" % (PROGRAM, arguments.output))


if __name__ == "__main__":
    main()
