#!/usr/bin/python3
"""The first impact on the downstream wall, read from the fluid app's gauge file (gauges 1 and 2:
Lobovsky et al.'s sensors 1 and 2, dam_break_lobovsky.par), in t sqrt(g/H) and p / (rho0 g H):
the onset at sensor 2 (the first p > 0.1 rho0 g H, linear between rows) and the first peak at each
sensor (the largest p within 0.5 of t sqrt(g/H) after the onset at sensor 2), read raw (every row),
averaged over the acoustic ringing period that follows the impact, averaged over 0.01, and read as the
experiment's 20 kHz recorder would (point samples or samples of the 50 us average, at random phase); the
first peak's width at half maximum and the mean pressure over 0.1 after the onset; against
the experiment's statistics (Lobovsky et al. 2014 Table 2, lobovsky_2014_pressure.txt: median and
2.5-97.5% band of the first peak over 100 repetitions) and TrixiParticles' converged H/400 sensors
(trixi_dam_break_reference_400.txt). The bounds are the issue's (issue 35 item 6); the later plateau
and second peak are plotted (plot_dam_break_validation.py pressure), not bounded.

    dam_break_pressure.py RUN.gauges.csv [--check | --check-onset]
    dam_break_pressure.py --series S1.dat S2.dat      # t sqrt(g/H), p / (rho g H) at sensors 1 and 2
"""
import argparse
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import dam_break_fronts as fronts  # noqa: E402

ONSET, PEAK_1, PEAK_2 = (2.33, 2.49), (2.0, 4.0), (1.5, 2.6)
EXPERIMENT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "lobovsky_2014_pressure.txt")
EXPERIMENT_H = 0.3  # m; the statistics are for H = 300 mm
EXPERIMENT_RHO_G_H_MBAR = 1000 * 9.81 * EXPERIMENT_H / 100  # 29.43 mbar
EXPERIMENT_RATE = 20000.0  # Hz: the experiment's sampling (Lobovsky et al. 2014)


def experiment_statistics():
    """{sensor: (centre in mm, median, 2.5% and 97.5% percentiles in rho g H)} of the first
    pressure peak (Lobovsky et al. 2014 Table 2, H = 300 mm)."""
    table = np.loadtxt(EXPERIMENT, ndmin=2)
    if table.shape[1] != 5 or not np.all((table[:, 3] <= table[:, 2]) & (table[:, 2] <= table[:, 4])):
        sys.exit("dam_break_pressure: '%s' is not sensor, centre, median, 2.5%%, 97.5%% with the median "
                 "inside its band" % EXPERIMENT)
    return {int(row[0]): (row[1], *(row[2:] / EXPERIMENT_RHO_G_H_MBAR)) for row in table}


def experiment_interval():
    """The experiment's sampling interval in t sqrt(g/H)."""
    return math.sqrt(9.81 / EXPERIMENT_H) / EXPERIMENT_RATE


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


def running_mean(T, p, width):
    """The centred mean of p over `width` of T at each row (trapezoid integral of the rows, so an
    uneven step counts by its length); rows closer than width / 2 to either end get nan."""
    integral = np.concatenate(([0.0], np.cumsum(0.5 * (p[1:] + p[:-1]) * np.diff(T))))
    low, high = T - 0.5 * width, T + 0.5 * width
    mean = (np.interp(high, T, integral) - np.interp(low, T, integral)) / width
    mean[(low < T[0]) | (high > T[-1])] = np.nan
    return mean


def ringing_period(T, series, onset, span=0.5):
    """The period of the acoustic ringing after the impact, one for all the sensors: the first
    maximum (after its first zero) of the sum of the autocorrelations of each p in `series` over
    [onset, onset + span], on a uniform grid at the rows' median interval, each less its cubic
    trend (the impact's rise and decay). nan if none is found."""
    dt = float(np.median(np.diff(T)))
    grid = np.arange(onset, min(onset + span, T[-1]), dt)
    if len(grid) < 16:
        return float("nan")
    correlation = 0
    for p in series:
        q = np.interp(grid, T, p)
        q = q - np.polyval(np.polyfit(grid - onset, q, 3), grid - onset)
        correlation = correlation + np.correlate(q, q, "full")[len(q) - 1:]
    negative = np.nonzero(correlation < 0)[0]
    if len(negative) == 0:
        return float("nan")
    rest = correlation[negative[0]:]
    peaks = np.nonzero((rest[1:-1] > rest[:-2]) & (rest[1:-1] >= rest[2:]) & (rest[1:-1] > 0))[0]
    return float((negative[0] + peaks[0] + 1) * dt) if len(peaks) else float("nan")


def read_every(T, p1, p2, interval, start):
    """The first impact of the series read at T = start, start + interval, ... (linear between rows)."""
    grid = np.arange(start, T[-1], interval)
    return first_impact(grid, np.interp(grid, T, p1), np.interp(grid, T, p2))


def point_samples(T, p1, p2, interval=0.01):
    """The first impact of the series read at T = 0, interval, 2 interval, ... (read_every), as
    TrixiParticles stores its sensors; and the range of the peaks over the ten phases of that grid
    shifted by interval / 10 (a spike shorter than the interval is missed or hit)."""
    phases = [read_every(T, p1, p2, interval, s) for s in np.arange(0, interval, interval / 10)]
    return (read_every(T, p1, p2, interval, 0.0), [min(p[k] for p in phases) for k in (1, 2)],
            [max(p[k] for p in phases) for k in (1, 2)])


def sampled_peaks(T, p1, p2, interval, integrate=True, phases=1000, seed=2014):
    """The first peaks as a recorder sampling every `interval` reads them (Lobovsky et al. 2014: 20 kHz):
    each series first averaged over one interval centred on each row when `integrate` (a sensor that
    integrates over its sampling time; without it, point samples), then read at phase + k interval,
    linear between rows, for `phases` phases drawn uniformly in [0, interval) with a fixed seed (the
    experiment's clock is not tied to the impact). Returns, per sensor, the median, 2.5% and 97.5%
    percentiles of the first peak over the phases."""
    if integrate:
        p1, p2 = (np.nan_to_num(running_mean(T, p, interval)) for p in (p1, p2))
    peaks = np.array([read_every(T, p1, p2, interval, T[0] + phase)[1:]
                      for phase in np.random.default_rng(seed).uniform(0, interval, phases)])
    return [tuple(np.percentile(peaks[:, k], (50, 2.5, 97.5))) for k in (0, 1)]


def peak_shape(T, p, onset, span=0.1):
    """The first peak's duration and what a slow sensor would read: its full width at half maximum (the
    rows around the largest p within [onset - 0.05, onset + 0.5] that stay above half of it), and the
    mean p over [onset, onset + span] (trapezoid rule)."""
    window = np.nonzero((T >= onset - 0.05) & (T <= onset + 0.5))[0]
    top = window[np.argmax(p[window])]
    first, last = top, top
    while first > window[0] and p[first - 1] > 0.5 * p[top]:
        first -= 1
    while last < window[-1] and p[last + 1] > 0.5 * p[top]:
        last += 1
    grid = np.linspace(onset, onset + span, 2001)
    return float(T[last] - T[first]), float(np.trapz(np.interp(grid, T, p), grid) / span)


def verdict(value, low, high):
    return "inside" if low <= value <= high else ("above" if value > high else "below")


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("run", nargs="?", help="the fluid app's gauge file")
    parser.add_argument("--series", nargs=2, metavar=("S1", "S2"),
                        help="instead of a run: two files of t sqrt(g/H), p / (rho g H) at sensors 1 and 2 (e.g. "
                             "a repetition of the experiment, docs/fluid-flow.md)")
    checks = parser.add_mutually_exclusive_group()
    checks.add_argument("--check", action="store_true", help="exit 1 unless the issue's bounds hold")
    checks.add_argument("--check-onset", action="store_true",
                        help="exit 1 unless the onset at sensor 2 is within the issue's bound (CI at H/25, whose "
                             "peaks are compared and reported, docs/fluid-flow.md)")
    args = parser.parse_args()
    if (args.run is None) == (args.series is None):
        parser.error("give a gauge file or --series, not both")
    if args.series:
        first, second = (np.loadtxt(path, ndmin=2) for path in args.series)
        T, p1, p2 = first[:, 0], first[:, 1], np.interp(first[:, 0], second[:, 0], second[:, 1])
        args.run, resolution = " and ".join(args.series), "the series' rows"
    else:
        run = fronts.GaugeFile(args.run)
        scale = run.rho0 * run.g * run.length
        T = run["t"] * math.sqrt(run.g / run.length)
        p1, p2 = run["p_1"] / scale, run["p_2"] / scale
        resolution = "dx = H/%.0f" % (run.length / run.dx)
    onset, peak1, peak2 = first_impact(T, p1, p2)
    experiment = experiment_statistics()
    around = (T >= onset - 0.05) & (T <= onset + 0.5)
    interval = float(np.median(np.diff(T[around]))) if np.count_nonzero(around) > 1 else float("nan")
    print("%s (%s): rows every %.2e of t sqrt(g/H) around the impact, the experiment's 20 kHz %.2e: "
          "the gauge is sampled %s" % (args.run, resolution, interval, experiment_interval(),
                                        "coarser" if interval > experiment_interval() else "finer"))
    print("  onset at sensor 2: t sqrt(g/H) = %.3f (bound [%g, %g]: %s)" % (onset, *ONSET, verdict(onset, *ONSET)))
    period = ringing_period(T, (p1, p2), onset)
    smoothed = first_impact(T, np.nan_to_num(running_mean(T, p1, period)), np.nan_to_num(running_mean(T, p2, period)))
    Tw, p1w = window_means(T, p1)
    _, p2w = window_means(T, p2)
    averaged = first_impact(Tw, np.nan_to_num(p1w), np.nan_to_num(p2w))
    sampled, low, high = point_samples(T, p1, p2)
    for k, raw, bound in ((1, peak1, PEAK_1), (2, peak2, PEAK_2)):
        centre, median, p_low, p_high = experiment[k]
        print("  first peak, sensor %d (centre %g mm at H = 0.3 m), rho0 g H: raw %.3f (the issue's bound [%g, %g]: "
              "%s; Lobovsky et al. Table 2: median %.3f, 2.5-97.5%% [%.3f, %.3f]: %s); averaged over the ringing "
              "period %.4f: %.3f (%s); averaged over 0.01: %.3f; read every 0.01: %.3f (%.2f-%.2f over the grid's phases)" %
              (k, centre, raw, *bound, verdict(raw, *bound), median, p_low, p_high, verdict(raw, p_low, p_high),
               period, smoothed[k], verdict(smoothed[k], p_low, p_high), averaged[k], sampled[k],
               low[k - 1], high[k - 1]))
    for integrate, what in ((False, "point samples"), (True, "samples of the average over each interval")):
        readings = sampled_peaks(T, p1, p2, experiment_interval(), integrate)
        print("  read as the experiment's 20 kHz recorder (%s, over 1000 random phases): first peak median "
              "[2.5%%, 97.5%%] %s" % (what, "; ".join("sensor %d %.3f [%.3f, %.3f] (Table 2 median %.3f)" % (
                  k + 1, *reading, experiment[k + 1][1]) for k, reading in enumerate(readings))))
    shapes = [peak_shape(T, p, onset) for p in (p1, p2)]
    print("  first peak's full width at half maximum: sensor 1 %.4f, sensor 2 %.4f of t sqrt(g/H); mean p over "
          "[onset, onset + 0.1]: sensor 1 %.3f, sensor 2 %.3f rho0 g H" % (shapes[0][0], shapes[1][0], shapes[0][1],
                                                                          shapes[1][1]))
    reference = np.loadtxt(fronts.REFERENCE)
    H = fronts.REFERENCE_H
    ref = first_impact(reference[:, 0] * math.sqrt(fronts.G / H), reference[:, 2] / (1000 * fronts.G * H),
                       reference[:, 3] / (1000 * fronts.G * H))
    print("  TrixiParticles H/400 (sampled every 0.01): onset %.3f, peaks %.3f, %.3f" % ref)
    for T0 in (4.0, 5.0, 6.0, 6.5, 7.0):
        if T0 <= T[-1]:
            k = int(np.argmin(np.abs(T - T0)))
            print("  t sqrt(g/H) = %.1f: p1 %.3f, p2 %.3f rho0 g H" % (T0, p1[k], p2[k]))
    if args.check or args.check_onset:
        ok = ONSET[0] <= onset <= ONSET[1]
        if args.check:
            ok = ok and PEAK_1[0] <= peak1 <= PEAK_1[1] and PEAK_2[0] <= peak2 <= PEAK_2[1]
        sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
