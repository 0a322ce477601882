"""A glass of the glass app (apps/glass) against the bounds of a glass: prints its relative density
scatter and its structure factor's peak and low-k mean (apps/glass/glass_quality.py) beside those
of the lattice and of a random set of the same count, and exits 1 unless the scatter is at most
SCATTER, the peak relative to the particle count, max S / N, at most PEAK (a lattice has 1: its
Bragg peak S = N) and the low-k mean at most LOW (random: about 1).

    check_glass.py glass.h5part SCATTER PEAK LOW [--json FILE]
"""
import argparse
import json
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "apps", "glass"))
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "apps", "plotting"))
import glass_quality  # noqa: E402
import h5part_plot  # noqa: E402

PROGRAM = "check_glass"


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("file")
    parser.add_argument("scatter", type=float)
    parser.add_argument("peak", type=float)
    parser.add_argument("low", type=float)
    parser.add_argument("--json", help="also write the figures and the verdict to this file")
    arguments = parser.parse_args()
    if not os.path.isfile(arguments.file):
        print("%s: '%s' does not exist (the run did not write it)" % (PROGRAM, arguments.file), file=sys.stderr)
        sys.exit(3)
    attributes = h5part_plot.attributes(arguments.file, PROGRAM)
    dimension = int(h5part_plot.number(attributes, "dimension", 3))
    time, data, _ = h5part_plot.read_step(arguments.file, None, PROGRAM)
    glass = glass_quality.quality(glass_quality.positions_of(data, dimension), data["rho"])
    per_side = int(round(glass["particles_per_side"]))
    lattice = glass_quality.structure_factor(glass_quality.lattice_positions(per_side, dimension))[1]
    random = glass_quality.structure_factor(np.random.default_rng(1).random((glass["particles"], dimension)))
    glass["lattice_peak_structure_factor"] = float(lattice.max())
    glass["random_low_k_structure_factor"] = float(random[1][random[0] <= 0.5 * per_side].mean())
    glass["time"] = float(time)
    glass["relative_peak_structure_factor"] = glass["peak_structure_factor"] / glass["particles"]
    passed = (glass["density_scatter"] <= arguments.scatter and
              glass["relative_peak_structure_factor"] <= arguments.peak and
              glass["low_k_structure_factor"] <= arguments.low)
    glass["bounds"] = {"density_scatter": arguments.scatter, "relative_peak_structure_factor": arguments.peak,
                       "low_k_structure_factor": arguments.low}
    glass["pass"] = bool(passed)
    print("glass %s (%dD, %d particles, t = %.4g): density scatter %.3e (bound %g); structure factor: peak %.2f = %.4f N "
          "at |m| = %.2f (bound %g N; lattice %.0f = N), low-k mean %.3f (bound %g; random %.3f): %s" %
          (arguments.file, dimension, glass["particles"], time, glass["density_scatter"], arguments.scatter,
           glass["peak_structure_factor"], glass["relative_peak_structure_factor"], glass["peak_wave_number"],
           arguments.peak,
           glass["lattice_peak_structure_factor"], glass["low_k_structure_factor"], arguments.low,
           glass["random_low_k_structure_factor"], "pass" if passed else "FAIL"))
    if arguments.json:
        with open(arguments.json, "w") as out:
            json.dump(glass, out, indent=1)
    sys.exit(0 if passed else 1)


if __name__ == "__main__":
    main()
