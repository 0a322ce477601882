"""The square test's measures on an output step, shared by plot_square.py and
tests/validation/check_square.py. The square's particles are those of id >= square_first_id (a
root attribute of the output): the measures follow the same (Lagrangian) particles, except the
corner cover, which measures where the dense phase is, whichever particles hold it.

- corner_cover: the fraction of the area of the four corner boxes of side CORNER (0.05) inside the
  original square's corners whose nearest particle belongs to the dense phase (the square's
  particles with rho > 2.5, as for the squareness), sampled on a grid of COVER_SAMPLES^2 points a
  box. A square that keeps its corners and its density covers 1 (0.90-0.99 at t = 0 from 32^2 to
  128^2: the smoothed contact trims the outermost row below 2.5); the circle of the same area
  (radius 0.282) does not reach the boxes (their nearest point is at 0.2 sqrt 2 = 0.283 from the
  centre), so a rounded square tends to 0, as does one whose corners lost their density. It
  measures the shape: particles that trade places inside the square leave it unchanged.
- corner_fill (reported): of the square's particles in the corner boxes with a density above 3 at
  the first step, the fraction still in a box with a density above 3. It follows particles, so it
  also counts motions that keep the shape: at 96^2 and 128^2 a row of the lattice lies within a
  tenth of a spacing of the boxes' inner edges (0.2995 and 0.2988 against 0.3), and a sub-spacing
  jitter takes that row (15-19% of the box's particles) out of the boxes (docs/square.md).
- dense_fraction: of the square's particles with a density above 3 at the first step (those more
  than about a kernel radius inside the contact), the fraction with a density above 3 now.
- interior_minimum_density: the smallest density of those particles now.
- squareness: (R - 1) / (sqrt 2 - 1), R the ratio of the dense phase's extent along the diagonals
  to that along the axes (the 98th percentile of the distance from the centre of the square's
  particles with rho > 2.5, the mean of the two phases, within 10 degrees of each direction): 1 for
  the square (R = sqrt 2), 0 for a circle.
"""
import numpy as np

CORNER = 0.05
DENSE = 3.0
COVER_SAMPLES = 50


def corner_boxes(x, y):
    """Whether each point lies in one of the corner boxes [1/4, 1/4 + c] x ... inside the square."""
    near_x = (np.abs(x - 0.25) <= CORNER) & (x >= 0.25) | (np.abs(x - 0.75) <= CORNER) & (x <= 0.75)
    near_y = (np.abs(y - 0.25) <= CORNER) & (y >= 0.25) | (np.abs(y - 0.75) <= CORNER) & (y <= 0.75)
    return near_x & near_y


def corner_cover(x, y, in_phase, samples=COVER_SAMPLES):
    """The fraction of the corner boxes' area whose nearest particle is in_phase (x, y in [0, 1))."""
    offsets = (np.arange(samples) + 0.5) * CORNER / samples
    covered = 0
    for corner_x, inward_x in ((0.25, 1.0), (0.75, -1.0)):
        for corner_y, inward_y in ((0.25, 1.0), (0.75, -1.0)):
            gx, gy = np.meshgrid(corner_x + inward_x * offsets, corner_y + inward_y * offsets)
            gx, gy = gx.ravel(), gy.ravel()
            # The nearest particle of a point in the box lies within half a box of it: particles are
            # far closer together than that.
            centre_x, centre_y = corner_x + inward_x * CORNER / 2, corner_y + inward_y * CORNER / 2
            near = (np.abs(x - centre_x) < CORNER) & (np.abs(y - centre_y) < CORNER)
            if not near.any():
                continue
            distance2 = (gx[:, None] - x[near][None, :]) ** 2 + (gy[:, None] - y[near][None, :]) ** 2
            covered += int(in_phase[near][np.argmin(distance2, axis=1)].sum())
    return covered / (4 * samples * samples)


def circle_corner_cover():
    """The fraction of the corner boxes' area that the circle of area 1/4 about the centre covers."""
    radius = np.sqrt(0.25 / np.pi)
    offsets = 0.25 - (np.arange(200) + 0.5) * CORNER / 200
    gx, gy = np.meshgrid(offsets, offsets)
    return float(np.mean(gx ** 2 + gy ** 2 < radius ** 2))


def extent_ratio(x, y):
    """R of `squareness` for the points (x, y) about (1/2, 1/2)."""
    dx, dy = x - 0.5, y - 0.5
    radius, angle = np.hypot(dx, dy), np.degrees(np.arctan2(dy, dx)) % 90.0
    diagonal = np.abs(angle - 45.0) <= 10.0
    axis = (angle <= 10.0) | (angle >= 80.0)
    if not diagonal.any() or not axis.any():
        return 1.0
    return float(np.percentile(radius[diagonal], 98) / np.percentile(radius[axis], 98))


def measures(first, now, first_id):
    """first, now: {dataset: array} of the first and the measured step (any particle order)."""
    def by_id(data):
        order = np.argsort(data["id"])
        return {k: np.asarray(v)[order] for k, v in data.items()}
    a, b = by_id(first), by_id(now)
    if not np.array_equal(a["id"], b["id"]):
        raise ValueError("the two steps hold different particles")
    square = a["id"] >= first_id
    dense_start = square & (a["rho"] > DENSE)
    in_corner_start = dense_start & corner_boxes(a["x"], a["y"])
    x, y = b["x"] % 1.0, b["y"] % 1.0
    in_corner_now = in_corner_start & corner_boxes(x, y) & (b["rho"] > DENSE)
    dense_now = square & (b["rho"] > 2.5)
    ratio = extent_ratio(x[dense_now], y[dense_now])
    return {
        "square_particles": int(square.sum()),
        "squareness": (ratio - 1.0) / (np.sqrt(2.0) - 1.0),
        "corner_cover": corner_cover(x, y, dense_now),
        "corner_particles_at_start": int(in_corner_start.sum()),
        "corner_fill": float(in_corner_now.sum() / max(in_corner_start.sum(), 1)),
        "circle_corner_cover": circle_corner_cover(),
        "dense_fraction": float((dense_start & (b["rho"] > DENSE)).sum() / max(dense_start.sum(), 1)),
        "interior_minimum_density": float(b["rho"][dense_start].min()),
        "largest_speed": float(np.sqrt(b["vx"] ** 2 + b["vy"] ** 2).max()),
    }
