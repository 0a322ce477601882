"""The square test's last step against its first (apps/square/square_analysis.py): prints the
squareness (1: square, 0: circle), the corner cover (the corner boxes' area still the square's;
1: corners kept; a circle of the same area: 0), the corner fill (reported: the particles still in
the boxes), the fraction of the square's dense particles (rho > 3 at the start) still above 3, and
their smallest density; exit 1 when the squareness is below SQUARE, the corner cover below CORNER
or the dense fraction below DENSE.

    check_square.py square.h5part SQUARE CORNER DENSE [--json FILE]
"""
import argparse
import json
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "apps", "square"))
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "apps", "plotting"))
import h5part_plot  # noqa: E402
import square_analysis  # noqa: E402

PROGRAM = "check_square"


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("file")
    parser.add_argument("square", type=float)
    parser.add_argument("corner", type=float)
    parser.add_argument("dense", type=float)
    parser.add_argument("--json", help="also write the figures and the verdict to this file")
    arguments = parser.parse_args()
    if not os.path.isfile(arguments.file):
        print("%s: '%s' does not exist (the run did not write it)" % (PROGRAM, arguments.file), file=sys.stderr)
        sys.exit(3)
    attributes = h5part_plot.attributes(arguments.file, PROGRAM)
    if "square_first_id" not in attributes:
        print("%s: '%s' is not an output of the square app (no square_first_id)" % (PROGRAM, arguments.file),
              file=sys.stderr)
        sys.exit(3)
    steps = h5part_plot.step_indices(arguments.file, PROGRAM)
    _, first, _ = h5part_plot.read_step(arguments.file, steps[0], PROGRAM)
    time, now, _ = h5part_plot.read_step(arguments.file, steps[-1], PROGRAM)
    result = square_analysis.measures(first, now, int(h5part_plot.number(attributes, "square_first_id", 0)))
    result["time"] = float(time)
    passed = result["squareness"] >= arguments.square and result["corner_cover"] >= arguments.corner and result["dense_fraction"] >= arguments.dense
    result["bounds"] = {"squareness": arguments.square, "corner_cover": arguments.corner, "dense_fraction": arguments.dense}
    result["pass"] = bool(passed)
    print("square test at t = %.4g, %d square particles: squareness %.3f (bound %g; square 1, circle 0), corner cover %.3f (bound %g; a circle of the same area "
          "%.3f), corner fill %.3f (reported; %d corner particles at the start), dense fraction %.3f (bound %g), smallest interior density %.3f, "
          "largest speed %.3g: %s" %
          (time, result["square_particles"], result["squareness"], arguments.square, result["corner_cover"], arguments.corner, result["circle_corner_cover"],
           result["corner_fill"], result["corner_particles_at_start"], result["dense_fraction"], arguments.dense,
           result["interior_minimum_density"], result["largest_speed"], "pass" if passed else "FAIL"))
    if arguments.json:
        with open(arguments.json, "w") as out:
            json.dump(result, out, indent=1)
    sys.exit(0 if passed else 1)


if __name__ == "__main__":
    main()
