"""The square test's measures (square_analysis.measures: squareness, corner cover, corner fill,
dense fraction) on two snapshots of SWIFT's SquareTest_2D (swiftsimio's layout: PartType0 with
Coordinates, Velocities, Densities, ParticleIDs), to set this code's square against an
independent one (docs/square.md, "Against SWIFT"). The square's particles are those inside
[1/4, 3/4]^2 in the first snapshot (SWIFT's makeIC.py removes the ambient lattice there).

    /usr/bin/python3 apps/square/measure_swift_square.py square_0000.hdf5 square_0020.hdf5
"""
import argparse
import os
import sys

import h5py
import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import square_analysis  # noqa: E402

PROGRAM = "measure_swift_square"


def read_snapshot(path):
    """(time, {dataset: array}) of a SWIFT snapshot, in the names square_analysis reads."""
    try:
        with h5py.File(path, "r") as f:
            gas = f["PartType0"]
            x, v = gas["Coordinates"][...], gas["Velocities"][...]
            data = {"x": x[:, 0], "y": x[:, 1], "vx": v[:, 0], "vy": v[:, 1], "rho": gas["Densities"][...].ravel(),
                    "id": gas["ParticleIDs"][...].ravel().astype(np.int64)}
            return float(f["Header"].attrs["Time"][()]), data
    except (OSError, KeyError) as error:
        print("%s: '%s' is not a SWIFT gas snapshot: %s" % (PROGRAM, path, error), file=sys.stderr)
        sys.exit(3)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("first")
    parser.add_argument("now")
    arguments = parser.parse_args()
    _, first = read_snapshot(arguments.first)
    time, now = read_snapshot(arguments.now)
    inside = (np.abs(first["x"] - 0.5) < 0.25) & (np.abs(first["y"] - 0.5) < 0.25)
    result = square_analysis.measures(first, now, int(first["id"][inside].min()))
    print("SWIFT square at t = %.4g, %d square particles: squareness %.3f, corner cover %.3f (circle %.3f), corner fill %.3f, "
          "dense fraction %.3f, smallest interior density %.3f, largest speed %.3g" %
          (time, result["square_particles"], result["squareness"], result["corner_cover"], result["circle_corner_cover"],
           result["corner_fill"], result["dense_fraction"], result["interior_minimum_density"], result["largest_speed"]))


if __name__ == "__main__":
    main()
