"""The quality of a glass (or of any periodic particle set in the unit box), shared by
tests/validation/check_glass.py and plot_glass.py:

- the relative density scatter std(rho) / mean(rho) of the SPH densities in the file;
- the structure factor S(k) = |sum_j exp(-i k.x_j)|^2 / N on the box's wave vectors k = 2 pi m
  (m integer, 0 < |m| <= 1.5 n, n = N^(1/D) the particles per side). A lattice of n per side has
  its Bragg peak S = N at |m| = n; a random (Poisson) set has S ~ 1 at every k; a glass has no peak
  and S << 1 at small k (its density fluctuations are suppressed on large scales: the "glass"
  property of White 1996 and of Gadget's and SWIFT's glass files). Two numbers separate them:
  `peak_structure_factor` (the largest S: N for the lattice, O(10) for a glass or random set) and
  `low_k_structure_factor` (the mean S over 0 < |m| <= n / 2: about 1 random, well below 1 glass).
"""
import numpy as np


def density_scatter(rho):
    rho = np.asarray(rho, dtype=float)
    return float(np.std(rho) / np.mean(rho))


def structure_factor(positions, radius_factor=1.5):
    """(|m| of every mode, S of it) for 0 < |m| <= radius_factor * n, with positions (N, D) in [0, 1)^D.
    The sums over particles are matrix products of the per-axis phases exp(-2 pi i m x)."""
    positions = np.asarray(positions, dtype=float)
    count, dimension = positions.shape
    per_side = count ** (1.0 / dimension)
    largest = int(np.floor(radius_factor * per_side))
    orders = np.arange(-largest, largest + 1)
    phases = [np.exp(-2j * np.pi * np.outer(positions[:, k], orders)) for k in range(dimension)]
    if dimension == 2:
        sums = phases[0].T @ phases[1]
        grids = np.meshgrid(orders, orders, indexing="ij")
    else:
        sums = np.empty((len(orders),) * 3, dtype=complex)
        for c, _ in enumerate(orders):
            sums[:, :, c] = (phases[0] * phases[2][:, c:c + 1]).T @ phases[1]
        grids = np.meshgrid(orders, orders, orders, indexing="ij")
    length = np.sqrt(sum(g.astype(float) ** 2 for g in grids))
    keep = (length > 0) & (length <= radius_factor * per_side + 1e-9)
    return length[keep], (np.abs(sums[keep]) ** 2) / count, per_side


def quality(positions, rho):
    length, factor, per_side = structure_factor(positions)
    low = length <= 0.5 * per_side
    return {
        "particles": int(len(rho)),
        "particles_per_side": float(per_side),
        "density_scatter": density_scatter(rho),
        "peak_structure_factor": float(factor.max()),
        "peak_wave_number": float(length[np.argmax(factor)]),
        "low_k_structure_factor": float(factor[low].mean()),
    }


def lattice_positions(per_side, dimension):
    """The cell-centre lattice of per_side^D points in the unit box (the problems' lattice)."""
    axis = (np.arange(per_side) + 0.5) / per_side
    grids = np.meshgrid(*([axis] * dimension), indexing="ij")
    return np.stack([g.ravel() for g in grids], axis=1)


def positions_of(data, dimension):
    return np.stack([data[a] for a in "xyz"[:dimension]], axis=1) % 1.0
