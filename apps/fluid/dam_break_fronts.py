#!/usr/bin/python3
"""The dam break's surge front, read from the fluid app's gauge file (gauge_file, column front_x:
the one front operator of specialization/fluid/surge_front.hh), against the converged reference
of TrixiParticles.jl (trixi_dam_break_reference_400.txt) and the experiment of Martin & Moyce
(1952, Table 2: martin_moyce_1952_table2.txt). The checks (tests/validation) and the plots use
these functions and nothing else.

    dam_break_fronts.py reference RUN.gauges.csv [RUN2 ...] [--tank-length 5.366]   # Lobovsky/Marrone geometry
    dam_break_fronts.py martin-moyce RUN.gauges.csv [RUN2.gauges.csv ...]   # the 1 x 2 column
    dam_break_fronts.py change COARSE.gauges.csv FINE.gauges.csv [FINER.gauges.csv]   # the 1 x 2 column
    dam_break_fronts.py lead RUN.gauges.csv [--raw-bound 0.16]              # raw error against the lead
    dam_break_fronts.py surface RUN.h5part [RUN2.h5part ...] [--times T ...] [--heights y/L ...]
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


def reference_curve(run):
    """(T = t sqrt(g/H), x_f / H) of a run in the Marrone / Lobovsky geometry (length = H)."""
    return run["t"] * math.sqrt(run.g / run.length), run["front_x"] / run.length


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
    T, x = reference_curve(run)
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
    mean, largest = relative_change(T_c, Z_c, T_f, Z_f, window)
    T_exp, _ = martin_moyce_points(*window)
    at_points = np.abs(np.interp(T_exp, T_f, Z_f) - np.interp(T_exp, T_c, Z_c)) / np.interp(T_exp, T_c, Z_c)
    return mean, largest, float(at_points.max())


def relative_change(T_c, x_c, T_f, x_f, window):
    """The relative difference of a front between a coarser (T_c, x_c) and a finer (T_f, x_f) run at
    the finer run's rows in `window` of T, the coarser one linear between rows: (mean, largest)."""
    if min(T_c[-1], T_f[-1]) < window[1]:
        sys.exit("dam_break_fronts: a run ends before T = %.2f" % window[1])
    keep = (T_f >= window[0]) & (T_f <= window[1])
    coarse = np.interp(T_f[keep], T_c, x_c)
    change = np.abs(x_f[keep] - coarse) / coarse
    return float(change.mean()), float(change.max())


def delayed_raw_errors(T, Z, delay, T_exp, Z_exp):
    """Relative errors of the curve Z(T - delay) against (T_exp, Z_exp) (positive: the curve ahead)."""
    return (np.interp(T_exp - delay, T, Z) - Z_exp) / Z_exp


def lead_table(run, leads):
    """Whether a raw bound fits a lead of the numerical front over Martin & Moyce. For each lead s:
    (model) the experiment taken as the run's own curve delayed by s, the raw errors the run would show
    (mean, largest), the part of the raw error a pure release delay s explains; (table) the run's curve
    delayed by (its best delay - s), so that its best delay is s, against Table 2's nine points: raw
    mean, largest, smallest. Rows (s, model mean, model largest, table mean, table largest, table
    smallest)."""
    T, Z = martin_moyce_curve(run)
    _, best, _ = against_martin_moyce(run)
    return best, [lead_row(T, Z, best, s) for s in leads]


def lead_row(T, Z, best, s):
    """One row of lead_table for the curve (T, Z) whose best delay against Table 2 is `best`."""
    T_exp, Z_exp = martin_moyce_points()
    delayed = np.interp(T_exp - s, T, Z)  # the "experiment"
    model = (np.interp(T_exp, T, Z) - delayed) / delayed
    table = delayed_raw_errors(T, Z, best - s, T_exp, Z_exp)
    return (s, model.mean(), model.max(), table.mean(), table.max(), table.min())


def lead_at_raw_bound(run, bound, model):
    """The lead s (see lead_table) at which the largest raw error reaches `bound`, by bisection on
    [0, 1] (the largest raw error grows with the lead); `model` picks the model column."""
    column = 2 if model else 4
    T, Z = martin_moyce_curve(run)
    _, best, _ = against_martin_moyce(run)
    low, high = 0.0, 1.0
    for _ in range(50):
        middle = 0.5 * (low + high)
        if lead_row(T, Z, best, middle)[column] < bound:
            low = middle
        else:
            high = middle
    return 0.5 * (low + high)


def observed_order(changes, resolutions):
    """The order p that makes the changes between three resolutions n0 < n1 < n2 (particles per
    length) those of an error C n^-p: changes[0] / changes[1] = (n0^-p - n1^-p) / (n1^-p - n2^-p)
    (bisection on p in [0.01, 6]; nan if the ratio is outside what that range gives), and the change
    it predicts from n2 to 2 n2."""
    n0, n1, n2 = resolutions
    ratio = changes[0] / changes[1]

    def model(p):
        return (n0 ** -p - n1 ** -p) / (n1 ** -p - n2 ** -p)

    low, high = 0.01, 6.0
    if not min(model(low), model(high)) <= ratio <= max(model(low), model(high)):
        return float("nan"), float("nan")
    for _ in range(100):
        middle = 0.5 * (low + high)
        if (model(middle) - ratio) * (model(low) - ratio) > 0:
            low = middle
        else:
            high = middle
    p = 0.5 * (low + high)
    return p, changes[1] * (n2 ** -p - (2 * n2) ** -p) / (n1 ** -p - n2 ** -p)


def wendland_c2(r, h):
    """The 2D Wendland C2 kernel of specialization/physics/kernels/wendland.hh (support 2h)."""
    s = np.clip(r / (2 * h), 0, 1)
    return 7 / (4 * math.pi * h * h) * (1 - s) ** 4 * (1 + 4 * s)


def surface_front(x, y, volume, h, height, spacing, bulk=(0.3, 0.15), length=1.0):
    """A front between particles: along the line at `height` above the floor, the largest x where the
    fluid's kernel sum, sum_b V_b W(X - x_b, h_b), falls to half its value in the water behind the tip
    (its median over x_max - bulk[0] length ... x_max - bulk[1] length, x_max the largest fluid x below
    0.2 length), linear between points spacing / 50 apart. A sharp edge of a uniform lattice gives
    the edge (the last particle plus spacing / 2) whatever the height; unlike the front operator the
    estimate moves continuously with the particles and sees how thick the tip is."""
    tip = x[y < 0.2 * length].max()
    grid = np.arange(tip - bulk[0] * length, tip + 3 * spacing, spacing / 50)
    near = (np.abs(y - height) < 2 * h) & (x > grid[0] - 2 * h.max())
    xs, ys, vs, hs = x[near], y[near], volume[near], h[near]
    c = np.array([np.sum(vs * wendland_c2(np.hypot(g - xs, height - ys), hs)) for g in grid])
    half = 0.5 * np.median(c[grid <= tip - bulk[1] * length])
    k = np.nonzero(c >= half)[0][-1]
    return float(grid[k] + (half - c[k]) / (c[k + 1] - c[k]) * (grid[k + 1] - grid[k]))


def surface_fronts(path, times, heights):
    """Z = x / a of a 1 x 2 column run's surface_front at its snapshots nearest each T in `times`,
    moved to T with the gauge file's front speed there (<stem>.gauges.csv beside the H5Part file):
    {T: (operator's Z, [Z at each height])}."""
    import h5py
    run = GaugeFile(re.sub(r"\.h5part$", "", path) + ".gauges.csv")
    a = run.length
    T_run, Z_run = martin_moyce_curve(run)
    result = {}
    with h5py.File(path, "r") as f:
        steps = {float(f[k].attrs["time"]) * math.sqrt(2 * run.g / a): k for k in f}
        for T in times:
            T_snap = min(steps, key=lambda t: abs(t - T))
            step = f[steps[T_snap]]
            fluid = step["kind"][:] == 0
            x, y, m, rho, h = (step[k][:][fluid] for k in ("x", "y", "m", "rho", "h"))
            speed = (np.interp(T_snap + 0.01, T_run, Z_run) - np.interp(T_snap - 0.01, T_run, Z_run)) / 0.02
            Z = [surface_front(x, y, m / rho, h, y0 * a, run.dx, length=a) / a + (T - T_snap) * speed
                 for y0 in heights]
            result[T] = (float(np.interp(T, T_run, Z_run)), Z)
    return run, result


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("against", choices=["reference", "martin-moyce", "change", "lead", "surface"])
    parser.add_argument("runs", nargs="+")
    parser.add_argument("--tank-length", type=float, default=5.366)
    parser.add_argument("--window", nargs=2, type=float, default=[1.0, 2.3],
                        help="reference: the span of t sqrt(g/H) compared (the issue's: 1.0 2.3)")
    parser.add_argument("--raw-bound", type=float, default=0.16, help="lead: the raw bound to invert (issue's 16%%)")
    parser.add_argument("--times", nargs="+", type=float, default=[1.8532, 2.8163],
                        help="surface: T of the snapshots compared (the L/100 run's at t = 0.1 s and its end)")
    parser.add_argument("--heights", nargs="+", type=float, default=[0.01, 0.02, 0.03],
                        help="surface: heights of the lines above the floor, in units of the column width")
    args = parser.parse_args()
    if args.against == "change":
        if len(args.runs) not in (2, 3):
            sys.exit("dam_break_fronts: change takes the coarser runs' gauge files, then the finest one's (2 or 3)")
        runs = [GaugeFile(path) for path in args.runs]
        means = []
        for coarse, fine in zip(runs[:-1], runs[1:]):
            mean, largest, at_points = front_change(coarse, fine)
            means.append(mean)
            print("front Z from L/%.0f to L/%.0f over 1 <= T <= 2.8: relative change mean %.4f, largest %.4f; at "
                  "Martin & Moyce's nine points largest %.4f" % (coarse.length / coarse.dx, fine.length / fine.dx,
                                                                 mean, largest, at_points))
        if len(runs) == 3:
            resolutions = [run.length / run.dx for run in runs]
            order, next_change = observed_order(means, resolutions)
            print("observed order of the mean change %.2f; it predicts %.4f from L/%.0f to L/%.0f" %
                  (order, next_change, resolutions[2], 2 * resolutions[2]))
        return
    if args.against == "surface":
        fronts = [surface_fronts(path, args.times, args.heights) for path in args.runs]
        for T in args.times:
            for run, result in fronts:
                operator, Z = result[T]
                print("T = %.4f, L/%.0f: operator Z %.4f; between particles at y = %s L: %s" % (
                    T, run.length / run.dx, operator, " ".join("%g" % y for y in args.heights),
                    " ".join("%.4f" % z for z in Z)))
            for (coarse, a), (fine, b) in zip(fronts[:-1], fronts[1:]):
                print("  change from L/%.0f to L/%.0f: operator %+.4f; between particles %s" % (
                    coarse.length / coarse.dx, fine.length / fine.dx, b[T][0] / a[T][0] - 1,
                    " ".join("%+.4f" % (z / w - 1) for z, w in zip(b[T][1], a[T][1]))))
        return
    previous = None
    for path in args.runs:
        run = GaugeFile(path)
        if args.against == "reference":
            mean, largest, mine, theirs = against_reference(run, args.tank_length, tuple(args.window))
            print("%s: dx = H/%.0f, front x_f/2H over %g <= t sqrt(g/H) <= %g against TrixiParticles H/400: "
                  "mean relative error %.4f, largest %.4f; wall arrival t sqrt(g/H) = %.3f (reference %.3f)" %
                  (path, run.length / run.dx, args.window[0], args.window[1], mean, largest, mine, theirs))
            if previous is not None:
                print("  front change from H/%.0f: mean %.4f, largest %.4f" % (
                    previous.length / previous.dx, *relative_change(*reference_curve(previous), *reference_curve(run),
                                                                    tuple(args.window))))
            previous = run
        elif args.against == "lead":
            best, rows = lead_table(run, np.arange(0.10, 0.3001, 0.025))
            print("%s: dx = L/%.0f, best delay %.3f. Raw errors against the lead s of the run over the experiment:" %
                  (path, run.length / run.dx, best))
            print("  s      model: experiment = run delayed by s (mean, largest)   Table 2: run delayed by %.3f - s "
                  "(mean, largest, smallest)" % best)
            for s, model_mean, model_max, mean, largest, smallest in rows:
                print("  %.3f  %.4f %.4f   %.4f %.4f %+.4f" % (s, model_mean, model_max, mean, largest, smallest))
            print("  the largest raw error reaches %g at s = %.3f (model), %.3f (Table 2)" % (
                args.raw_bound, lead_at_raw_bound(run, args.raw_bound, True),
                lead_at_raw_bound(run, args.raw_bound, False)))
        else:
            raw, shift, mean = against_martin_moyce(run)
            print("%s: dx = L/%.0f, against Martin & Moyce Table 2 (9 points, 1 <= T <= 2.8): raw errors %s "
                  "(mean %.4f, largest %.4f); best delay of the run %.3f, mean error after it %.4f" %
                  (path, run.length / run.dx, " ".join("%+.3f" % e for e in raw), np.mean(np.abs(raw)),
                   np.max(np.abs(raw)), shift, mean))


if __name__ == "__main__":
    main()
