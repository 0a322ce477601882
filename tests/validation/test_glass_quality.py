"""The glass measures (apps/glass/glass_quality.py) on sets whose answer is known: the cell-centre
lattice has its Bragg peaks S = N at |m| = n, n sqrt 2, ... and S = 0 below it; a random (Poisson) set has S ~ 1
(mean over the low-k modes within 0.3 of 1); the density scatter of a constant field is 0.
Exit 1 on any mismatch."""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "apps", "glass"))
import glass_quality  # noqa: E402


def main():
    failures = []
    for dimension, per_side in ((2, 24), (3, 10)):
        lattice = glass_quality.lattice_positions(per_side, dimension)
        count = len(lattice)
        measures = glass_quality.quality(lattice, np.ones(count))
        bragg = measures["peak_wave_number"] / per_side  # |m| / n of a reciprocal lattice vector: 1, sqrt 2, ...
        if abs(measures["peak_structure_factor"] - count) > 1e-6 * count or abs(bragg ** 2 - round(bragg ** 2)) > 1e-9:
            failures.append("%dD lattice: peak %s at |m| = %s, expected %d at a multiple of %d" %
                            (dimension, measures["peak_structure_factor"], measures["peak_wave_number"], count, per_side))
        if measures["low_k_structure_factor"] > 1e-20 * count or measures["density_scatter"] != 0:
            failures.append("%dD lattice: low-k S %s, scatter %s, expected 0" %
                            (dimension, measures["low_k_structure_factor"], measures["density_scatter"]))
        random = glass_quality.quality(np.random.default_rng(7).random((count, dimension)), np.ones(count))
        if not 0.7 < random["low_k_structure_factor"] < 1.3:
            failures.append("%dD random: low-k S %s, expected about 1" % (dimension, random["low_k_structure_factor"]))
        print("%dD, %d points: lattice peak %.1f at |m| = %.1f, low-k %.2e; random peak %.1f, low-k %.3f" %
              (dimension, count, measures["peak_structure_factor"], measures["peak_wave_number"],
               measures["low_k_structure_factor"], random["peak_structure_factor"], random["low_k_structure_factor"]))
    for failure in failures:
        print("test_glass_quality: " + failure, file=sys.stderr)
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
