"""The square test's measures on an output step, shared by plot_square.py and
tests/validation/check_square.py. The square's particles are those of id >= square_first_id (a
root attribute of the output): the measures follow the same (Lagrangian) particles.

- corner_fill: of the square's particles that lie in the four corner boxes of side CORNER (0.05)
  inside the original square's corners with a density above 3 at the first step, the fraction that
  still lie in a corner box with a density above 3. A square that keeps its corners keeps 1; the
  circle of the same area (radius 0.282) does not reach the boxes (their nearest point is at
  0.2 sqrt 2 = 0.283 from the centre), so a rounded square tends to 0.
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


def corner_boxes(x, y):
    """Whether each point lies in one of the corner boxes [1/4, 1/4 + c] x ... inside the square."""
    near_x = (np.abs(x - 0.25) <= CORNER) & (x >= 0.25) | (np.abs(x - 0.75) <= CORNER) & (x <= 0.75)
    near_y = (np.abs(y - 0.25) <= CORNER) & (y >= 0.25) | (np.abs(y - 0.75) <= CORNER) & (y <= 0.75)
    return near_x & near_y


def circle_corner_fill():
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
        "corner_particles_at_start": int(in_corner_start.sum()),
        "corner_fill": float(in_corner_now.sum() / max(in_corner_start.sum(), 1)),
        "circle_corner_fill": circle_corner_fill(),
        "dense_fraction": float((dense_start & (b["rho"] > DENSE)).sum() / max(dense_start.sum(), 1)),
        "interior_minimum_density": float(b["rho"][dense_start].min()),
        "largest_speed": float(np.sqrt(b["vx"] ** 2 + b["vy"] ** 2).max()),
    }
