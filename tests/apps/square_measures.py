"""Checks of the square test's measures (apps/square/square_analysis.py) on particle sets whose
answers are known (docs/square.md, "Beyond 64^2"):

- the set-up itself (the app's two lattices, rho 1 and 4): corner cover 1, corner fill 1;
- the square's particles trading places (the same positions and densities, shuffled ids): the
  cover, a measure of the shape, stays 1; the fill, which follows particles, falls towards the
  chance that a particle lands in a box again;
- a quarter disc of radius r cut from every corner (its particles become the light phase): the
  cover is 1 - pi r^2 / (4 c^2) of the boxes of side c;
- the corners' particles in place but below rho = 2.5: cover 0;
- the circle of the same area (the square's lattice inside radius sqrt(1 / (4 pi))): cover about 0,
  as the circle's own area fraction of the boxes;
- SWIFT's snapshots (measure_swift_square.py): the rounded square written in SWIFT's layout (ids
  from 1, float densities) reads back as the same particles and gives the same measures.
Exit 1 with the failures listed.
"""
import math
import os
import subprocess
import sys
import tempfile

import h5py
import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "apps", "square"))
import square_analysis as analysis  # noqa: E402

failures = []


def expect(ok, what):
    if not ok:
        failures.append(what)
    print("%s: %s" % ("ok" if ok else "FAIL", what))


def set_up(n):
    """The app's particles: cell centres of an n-lattice outside [1/4, 3/4]^2 (ids first) and of a
    2n-lattice inside it; rho 1 and 4."""
    def lattice(m):
        c = (np.arange(m) + 0.5) / m
        x, y = np.meshgrid(c, c)
        return x.ravel(), y.ravel()
    def inside(x, y):
        return (x > 0.25) & (x < 0.75) & (y > 0.25) & (y < 0.75)
    ox, oy = lattice(n)
    keep = ~inside(ox, oy)
    ox, oy = ox[keep], oy[keep]
    ix, iy = lattice(2 * n)
    keep = inside(ix, iy)
    ix, iy = ix[keep], iy[keep]
    x, y = np.concatenate([ox, ix]), np.concatenate([oy, iy])
    rho = np.concatenate([np.ones(ox.size), np.full(ix.size, 4.0)])
    data = {"id": np.arange(x.size), "x": x, "y": y, "vx": np.zeros(x.size), "vy": np.zeros(x.size), "rho": rho}
    return data, ox.size


def with_changes(data, **changes):
    out = {k: v.copy() for k, v in data.items()}
    out.update(changes)
    return out


first, first_id = set_up(64)
square = first["id"] >= first_id

result = analysis.measures(first, first, first_id)
expect(result["corner_cover"] == 1.0 and result["corner_fill"] == 1.0,
       "set-up: cover %.3f, fill %.3f (both 1)" % (result["corner_cover"], result["corner_fill"]))

# Shuffle the square particles' positions among themselves: the same shape, other particles.
order = np.random.default_rng(7).permutation(np.flatnonzero(square))
shuffled = with_changes(first, x=first["x"].copy(), y=first["y"].copy())
shuffled["x"][square] = first["x"][order]
shuffled["y"][square] = first["y"][order]
result = analysis.measures(first, shuffled, first_id)
in_boxes = analysis.corner_boxes(first["x"][square], first["y"][square]).mean()
expect(result["corner_cover"] == 1.0, "shuffled square: cover %.3f (1: the shape is the same)" % result["corner_cover"])
expect(result["corner_fill"] < 3 * in_boxes,
       "shuffled square: fill %.3f (about the boxes' share of the square, %.3f)" % (result["corner_fill"], in_boxes))

# A quarter disc of radius r cut from each corner of the square.
radius = 0.025
corner_x = np.where(first["x"] < 0.5, 0.25, 0.75)
corner_y = np.where(first["y"] < 0.5, 0.25, 0.75)
cut = square & (np.hypot(first["x"] - corner_x, first["y"] - corner_y) < radius)
rounded = with_changes(first, rho=np.where(cut, 1.0, first["rho"]))
result = analysis.measures(first, rounded, first_id)
exact = 1 - math.pi * radius ** 2 / (4 * analysis.CORNER ** 2)
expect(abs(result["corner_cover"] - exact) < 0.02,
       "corners cut to radius %g: cover %.3f (exact %.3f)" % (radius, result["corner_cover"], exact))

# The corner boxes' particles in place, their density gone: those within a spacing of the boxes
# too, which are the nearest particles of the boxes' inner edges.
spacing = 1 / 128
grown = ((np.abs(first["x"] - corner_x) <= analysis.CORNER + spacing) &
         (np.abs(first["y"] - corner_y) <= analysis.CORNER + spacing))
boxes = square & grown
thinned = with_changes(first, rho=np.where(boxes, 2.0, first["rho"]))
result = analysis.measures(first, thinned, first_id)
expect(result["corner_cover"] == 0.0 and result["corner_fill"] == 0.0,
       "corners (and a spacing around them) below rho 2.5: cover %.3f, fill %.3f (both 0)" % (result["corner_cover"], result["corner_fill"]))

# The circle of the same area: the dense phase is the square's lattice within sqrt(1 / (4 pi)).
circle = np.hypot(first["x"] - 0.5, first["y"] - 0.5) < math.sqrt(0.25 / math.pi)
round_data = with_changes(first, rho=np.where(square & ~circle, 1.0, first["rho"]))
result = analysis.measures(first, round_data, first_id)
# The circle's outermost particles lie within half a spacing of the boxes' innermost corners, the
# nearest particles of a few sample points there.
expect(result["corner_cover"] < 0.01 and result["circle_corner_cover"] == 0.0,
       "circle of the same area: cover %.3f (below 0.01), the circle's share of the boxes %.3f (0)" %
       (result["corner_cover"], result["circle_corner_cover"]))

# SWIFT's layout: the square's particles are found from the first snapshot's positions.
def write_swift_snapshot(path, data, time):
    with h5py.File(path, "w") as f:
        f.create_group("Header").attrs["Time"] = time
        gas = f.create_group("PartType0")
        zeros = np.zeros(data["x"].size)
        gas["Coordinates"] = np.column_stack([data["x"], data["y"], zeros])
        gas["Velocities"] = np.column_stack([data["vx"], data["vy"], zeros]).astype(np.float32)
        gas["Densities"] = data["rho"].astype(np.float32)
        gas["ParticleIDs"] = (data["id"] + 1).astype(np.uint64)


tool = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "apps", "square", "measure_swift_square.py")
with tempfile.TemporaryDirectory() as folder:
    start, end = os.path.join(folder, "square_0000.hdf5"), os.path.join(folder, "square_0020.hdf5")
    write_swift_snapshot(start, first, 0.0)
    write_swift_snapshot(end, rounded, 2.0)
    printed = subprocess.run([sys.executable, tool, start, end], capture_output=True, text=True)
    expected = analysis.measures(first, rounded, first_id)
    line = "t = 2, %d square particles: squareness %.3f, corner cover %.3f" % (
        expected["square_particles"], expected["squareness"], expected["corner_cover"])
    expect(printed.returncode == 0 and line in printed.stdout,
           "SWIFT snapshots: '%s' in the tool's output '%s'" % (line, printed.stdout.strip() + printed.stderr.strip()))
    bad = os.path.join(folder, "not_swift.hdf5")
    with h5py.File(bad, "w") as f:
        f.create_group("Header")
    printed = subprocess.run([sys.executable, tool, bad, end], capture_output=True, text=True)
    expect(printed.returncode == 3 and "not_swift.hdf5" in printed.stderr and "is not a SWIFT gas snapshot" in printed.stderr,
           "a file without PartType0: exit 3 naming it (%d, '%s')" % (printed.returncode, printed.stderr.strip()))

if failures:
    print("square_measures: %d failure(s)" % len(failures), file=sys.stderr)
    sys.exit(1)
