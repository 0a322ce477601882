"""The Gresho-Chan vortex's exact (steady) state and the binned L1 error of a run's azimuthal
velocity, shared by plot_gresho.py and tests/validation/check_gresho.py.

L1 = (1/N) sum over N = 25 radial bins of width 0.02 in 0 <= r < 0.5 of |<v_phi> - <v_phi exact>|,
both means over the bin's particles (the exact one at each particle's radius, so a bin's
curvature is not counted as error): the measure of Springel (2010, MNRAS 401, 791, sec. 8.2,
fig. 29) and Hopkins (2015, MNRAS 450, 53, sec. 4.1.2, fig. 5) up to the choice of bins.
"""
import numpy as np

BINS = 25
WIDTH = 0.02


def azimuthal_velocity(r):
    return np.where(r < 0.2, 5.0 * r, np.where(r < 0.4, 2.0 - 5.0 * r, 0.0))


def pressure(r):
    safe = np.maximum(r, 1e-300)
    return np.where(r < 0.2, 5.0 + 12.5 * r * r,
                    np.where(r < 0.4, 9.0 + 12.5 * r * r - 20.0 * r + 4.0 * np.log(5.0 * safe), 3.0 + 4.0 * np.log(2.0)))


def polar(data):
    x, y = data["x"], data["y"]
    r = np.sqrt(x * x + y * y)
    safe = np.where(r > 0, r, 1.0)
    v_phi = (x * data["vy"] - y * data["vx"]) / safe
    return r, v_phi


def binned(r, values):
    which = np.floor(r / WIDTH).astype(int)
    keep = which < BINS
    sums = np.bincount(which[keep], weights=values[keep], minlength=BINS)
    count = np.bincount(which[keep], minlength=BINS)
    return (np.arange(BINS) + 0.5) * WIDTH, sums / np.maximum(count, 1), count


def l1_error(r, v_phi):
    centres, mean, count = binned(r, v_phi)
    _, exact, _ = binned(r, azimuthal_velocity(r))
    used = count > 0
    return float(np.abs(mean - exact)[used].mean())
