#!/usr/bin/python3
"""The dam break's surge front, read from the fluid app's gauge file (gauge_file, column front_x:
the one front operator of specialization/fluid/surge_front.hh), against the converged reference
of TrixiParticles.jl (trixi_dam_break_reference_400.txt) and the experiment of Martin & Moyce
(1952, Table 2: martin_moyce_1952_table2.txt). The checks (tests/validation) and the plots use
these functions and nothing else.

    dam_break_fronts.py reference RUN.gauges.csv [--tank-length 5.366]      # Lobovsky/Marrone geometry
    dam_break_fronts.py martin-moyce RUN.gauges.csv [RUN2.gauges.csv ...]   # the 1 x 2 column
    dam_break_fronts.py change COARSE.gauges.csv FINE.gauges.csv             # the 1 x 2 column
"""
import argparse
import math
import os
import re
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
REFERENCE = os.path.join(HERE, "trixi_dam_break_reference_400.txt")
MARTIN_MOYCE = os.path.join(HERE, "martin_moyce_1952_table2.txt")
REFERENCE_H, REFERENCE_DX, REFERENCE_TANK = 0.6, 0.0015, 2146 * 0.0015  # floor(5.366 H / dx) dx
G = 9.81


class GaugeFile:
    """A gauge file: its length, dx and g from the first header line, its columns by name."""

    def __init__(self, path):
        self.path = path
        columns = None
        with open(path) as f:
            header = f.readline()
            for line in f:
                if line.startswith("# step,"):
                    columns = line[2:].strip().split(",")
        found = re.search(r"length ([^ ]+) m, dx ([^ ]+) m, rho0 ([^,]+), g ([^ \n]+)", header)
        if not found or columns is None:
            sys.exit("dam_break_fronts: '%s' is not a gauge file of the fluid app (gauge_file)" % path)
        self.length, self.dx, self.rho0, self.g = (float(v) for v in found.groups())
        with open(path) as f:  # gauge_smoothing, named in the gauges' header lines when not 1
            smoothing = re.search(r"smoothing length ([^ ]+) h", f.read(4096))
        self.smoothing = float(smoothing.group(1)) if smoothing else 1.0
        data = np.loadtxt(path, delimiter=",", comments="#", ndmin=2)
        if data.shape[0] < 2:
            sys.exit("dam_break_fronts: '%s' has fewer than 2 rows" % path)
        self.columns = {name: data[:, i] for i, name in enumerate(columns)}

    def __getitem__(self, name):
        return self.columns[name]


def reference_front():
    """(T = t sqrt(g/H), x_f / H) of the H/400 reference: its largest fluid x plus dx/2."""
    data = np.loadtxt(REFERENCE)
    H = REFERENCE_H
    return data[:, 0] * math.sqrt(G / H), (data[:, 1] + 0.5 * REFERENCE_DX) / H


def arrival(T, x, wall):
    """The first T at which the front x reaches `wall` (linear between rows), or nan."""
    above = np.nonzero(x >= wall)[0]
    if len(above) == 0:
        return float("nan")
    i = above[0]
    if i == 0:
        return float(T[0])
    return float(T[i - 1] + (wall - x[i - 1]) / (x[i] - x[i - 1]) * (T[i] - T[i - 1]))


def against_reference(run, tank_length=5.366, window=(1.0, 2.3)):
    """The run's front against the reference over `window` of T: (mean, max relative error of
    x_f / 2H, the run's wall arrival, the reference's). Arrival: the front within dx/2 of the far
    wall (the last particle's centre within one spacing), each with its own dx."""
    H = run.length
    T = run["t"] * math.sqrt(run.g / H)
    x = run["front_x"] / H
    T_ref, x_ref = reference_front()
    keep = (T_ref >= window[0]) & (T_ref <= window[1])
    if T[-1] < window[1]:
        sys.exit("dam_break_fronts: '%s' ends at T = %.3f, before %.2f" % (run.path, T[-1], window[1]))
    error = np.abs(np.interp(T_ref[keep], T, x) - x_ref[keep]) / x_ref[keep]
    tank = math.floor(tank_length * H / run.dx + 1e-9) * run.dx / H
    mine = arrival(T, x, tank - 0.5 * run.dx / H)
    theirs = arrival(T_ref, x_ref, (REFERENCE_TANK - 0.5 * REFERENCE_DX) / REFERENCE_H)
    return float(error.mean()), float(error.max()), mine, theirs


def martin_moyce_points(low=1.0, high=2.8):
    data = np.loadtxt(MARTIN_MOYCE)
    keep = (data[:, 0] >= low) & (data[:, 0] <= high)
    return data[keep, 0], data[keep, 1]


def martin_moyce_curve(run):
    """(T = t sqrt(2 g / a), Z = x_f / a) of a run in the 1 x 2 column (length = a)."""
    a = run.length
    return run["t"] * math.sqrt(2 * run.g / a), run["front_x"] / a


def against_martin_moyce(run):
    """The run against Table 2's nine points in 1 <= T <= 2.8: the raw relative errors (signed:
    positive where the run is ahead), the best constant delay s of the run's curve (Z_run(T - s)
    against the experiment, s in [0, 0.6] to 1e-3, least mean error) and the mean error after it."""
    T, Z = martin_moyce_curve(run)
    T_exp, Z_exp = martin_moyce_points()
    if T[-1] < T_exp[-1]:
        sys.exit("dam_break_fronts: '%s' ends at T = %.3f, before %.2f" % (run.path, T[-1], T_exp[-1]))
    raw = (np.interp(T_exp, T, Z) - Z_exp) / Z_exp
    shifts = np.arange(0, 0.6001, 0.001)
    means = [np.mean(np.abs(np.interp(T_exp - s, T, Z) - Z_exp) / Z_exp) for s in shifts]
    best = int(np.argmin(means))
    return raw, float(shifts[best]), float(means[best])


def front_change(coarse, fine, window=(1.0, 2.8)):
    """How much the front of the 1 x 2 column moves from one resolution to the next: the relative
    difference of Z between the two runs at the finer run's rows in `window` of T (mean, largest),
    and at Martin & Moyce's nine points (largest)."""
    T_c, Z_c = martin_moyce_curve(coarse)
    T_f, Z_f = martin_moyce_curve(fine)
    if min(T_c[-1], T_f[-1]) < window[1]:
        sys.exit("dam_break_fronts: a run ends before T = %.2f" % window[1])
    keep = (T_f >= window[0]) & (T_f <= window[1])
    change = np.abs(Z_f[keep] - np.interp(T_f[keep], T_c, Z_c)) / np.interp(T_f[keep], T_c, Z_c)
    T_exp, _ = martin_moyce_points(*window)
    at_points = np.abs(np.interp(T_exp, T_f, Z_f) - np.interp(T_exp, T_c, Z_c)) / np.interp(T_exp, T_c, Z_c)
    return float(change.mean()), float(change.max()), float(at_points.max())


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("against", choices=["reference", "martin-moyce", "change"])
    parser.add_argument("runs", nargs="+")
    parser.add_argument("--tank-length", type=float, default=5.366)
    parser.add_argument("--window", nargs=2, type=float, default=[1.0, 2.3],
                        help="reference: the span of t sqrt(g/H) compared (the issue's: 1.0 2.3)")
    args = parser.parse_args()
    if args.against == "change":
        if len(args.runs) != 2:
            sys.exit("dam_break_fronts: change takes the coarser run's gauge file, then the finer one's")
        coarse, fine = GaugeFile(args.runs[0]), GaugeFile(args.runs[1])
        mean, largest, at_points = front_change(coarse, fine)
        print("front Z from L/%.0f to L/%.0f over 1 <= T <= 2.8: relative change mean %.4f, largest %.4f; at Martin & "
              "Moyce's nine points largest %.4f" % (coarse.length / coarse.dx, fine.length / fine.dx, mean, largest,
                                                    at_points))
        return
    for path in args.runs:
        run = GaugeFile(path)
        if args.against == "reference":
            mean, largest, mine, theirs = against_reference(run, args.tank_length, tuple(args.window))
            print("%s: dx = H/%.0f, front x_f/2H over %g <= t sqrt(g/H) <= %g against TrixiParticles H/400: "
                  "mean relative error %.4f, largest %.4f; wall arrival t sqrt(g/H) = %.3f (reference %.3f)" %
                  (path, run.length / run.dx, args.window[0], args.window[1], mean, largest, mine, theirs))
        else:
            raw, shift, mean = against_martin_moyce(run)
            print("%s: dx = L/%.0f, against Martin & Moyce Table 2 (9 points, 1 <= T <= 2.8): raw errors %s "
                  "(mean %.4f, largest %.4f); best delay of the run %.3f, mean error after it %.4f" %
                  (path, run.length / run.dx, " ".join("%+.3f" % e for e in raw), np.mean(np.abs(raw)),
                   np.max(np.abs(raw)), shift, mean))


if __name__ == "__main__":
    main()
