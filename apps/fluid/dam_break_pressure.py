#!/usr/bin/python3
"""The first impact on the downstream wall, read from the fluid app's gauge file (gauges 1 and 2:
Lobovsky et al.'s sensors 1 and 2, dam_break_lobovsky.par), in t sqrt(g/H) and p / (rho0 g H):
the onset at sensor 2 (the first p > 0.1 rho0 g H, linear between rows) and the first peak at each
sensor (the largest p within 0.5 of t sqrt(g/H) after the onset at sensor 2); the same for
TrixiParticles' converged H/400 sensors (trixi_dam_break_reference_400.txt). The bounds are the
issue's (issue 35 item 6); the later plateau and second peak are plotted
(plot_dam_break_validation.py pressure), not bounded.

    dam_break_pressure.py RUN.gauges.csv [--check]
"""
import argparse
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import dam_break_fronts as fronts  # noqa: E402

ONSET, PEAK_1, PEAK_2 = (2.33, 2.49), (2.0, 4.0), (1.5, 2.6)


def first_impact(T, p1, p2):
    above = np.nonzero(p2 > 0.1)[0]
    if len(above) == 0:
        return float("nan"), float("nan"), float("nan")
    i = above[0]
    onset = T[i] if i == 0 else T[i - 1] + (0.1 - p2[i - 1]) / (p2[i] - p2[i - 1]) * (T[i] - T[i - 1])
    window = (T >= onset - 0.05) & (T <= onset + 0.5)
    return float(onset), float(p1[window].max()), float(p2[window].max())


def window_means(T, p, width=0.01):
    """p averaged over consecutive windows of `width` in T (the reference's output interval, a
    sensor of finite response), at the windows' ends."""
    edges = np.arange(T[0], T[-1], width)
    index = np.searchsorted(T, edges)
    means = [p[a:b].mean() if b > a else np.nan for a, b in zip(index[:-1], index[1:])]
    return edges[1:], np.array(means)


def point_samples(T, p1, p2, interval=0.01):
    """The first impact of the series read at T = 0, interval, 2 interval, ... (linear between
    rows), as TrixiParticles stores its sensors; and the range of the peaks over the ten phases
    of that grid shifted by interval / 10 (a spike shorter than the interval is missed or hit)."""
    def at(shift):
        grid = np.arange(0, T[-1] - shift, interval) + shift
        return first_impact(grid, np.interp(grid, T, p1), np.interp(grid, T, p2))
    phases = [at(s) for s in np.arange(0, interval, interval / 10)]
    return at(0.0), [min(p[k] for p in phases) for k in (1, 2)], [max(p[k] for p in phases) for k in (1, 2)]


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("run")
    parser.add_argument("--check", action="store_true", help="exit 1 unless the issue's bounds hold")
    args = parser.parse_args()
    run = fronts.GaugeFile(args.run)
    scale = run.rho0 * run.g * run.length
    T = run["t"] * math.sqrt(run.g / run.length)
    onset, peak1, peak2 = first_impact(T, run["p_1"] / scale, run["p_2"] / scale)
    Tw, p1w = window_means(T, run["p_1"] / scale)
    _, p2w = window_means(T, run["p_2"] / scale)
    averaged = first_impact(Tw, np.nan_to_num(p1w), np.nan_to_num(p2w))
    print("  averaged over windows of 0.01 in t sqrt(g/H) (the reference's sampling): onset %.3f, peaks %.3f, %.3f" %
          averaged)
    sampled, low, high = point_samples(T, run["p_1"] / scale, run["p_2"] / scale)
    print("  read every 0.01 of t sqrt(g/H) as TrixiParticles stores its sensors: peaks %.3f, %.3f (over the grid's "
          "phases %.2f-%.2f, %.2f-%.2f)" % (sampled[1], sampled[2], low[0], high[0], low[1], high[1]))
    reference = np.loadtxt(fronts.REFERENCE)
    H = fronts.REFERENCE_H
    ref = first_impact(reference[:, 0] * math.sqrt(fronts.G / H), reference[:, 2] / (1000 * fronts.G * H),
                       reference[:, 3] / (1000 * fronts.G * H))
    print("%s (dx = H/%.0f): onset at sensor 2 t sqrt(g/H) = %.3f (bound [%g, %g]); first peak sensor 1 %.3f rho0 g H "
          "(bound [%g, %g]), sensor 2 %.3f (bound [%g, %g]); TrixiParticles H/400 (sampled every 0.01): onset %.3f, "
          "peaks %.3f, %.3f" % (args.run, run.length / run.dx, onset, *ONSET, peak1, *PEAK_1, peak2, *PEAK_2, *ref))
    for T0 in (4.0, 5.0, 6.0, 6.5, 7.0):
        k = int(np.argmin(np.abs(T - T0)))
        print("  t sqrt(g/H) = %.1f: p1 %.3f, p2 %.3f rho0 g H" % (T0, run["p_1"][k] / scale, run["p_2"][k] / scale))
    if args.check:
        ok = ONSET[0] <= onset <= ONSET[1] and PEAK_1[0] <= peak1 <= PEAK_1[1] and PEAK_2[0] <= peak2 <= PEAK_2[1]
        sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
