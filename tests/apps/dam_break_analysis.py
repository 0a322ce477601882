"""Checks of the dam break's analysis (apps/fluid/dam_break_fronts.py, dam_break_pressure.py) on
synthetic data whose answers are known in closed form (docs/fluid-flow.md, "the three bounds not met"):

- lead_table / lead_at_raw_bound: a run that is Martin & Moyce's Table 2 advanced by 0.2 in T has its
  best delay at 0.2; there its Table 2 errors are those of the model (the experiment = the run delayed
  by the lead), and at the inverted lead the largest raw error is the bound;
- relative_change: a finer front ahead of the coarser by a known fraction gives that fraction back;
- observed_order: changes C (n0^-p - n1^-p), C (n1^-p - n2^-p) give back p and C (n2^-p - (2 n2)^-p);
- surface_front: a block of lattice water ends at its last particle plus half a spacing at any height,
  and moves with the particles by fractions of a spacing (the front operator moves by whole particles);
- sampled_peaks, peak_shape: a triangular spike of half-width a sampled every d at random phases peaks
  at P (1 - u d / (2a)) with u uniform in [0, 1] (median P (1 - d / (4a))); averaged over d first, its
  peak is lower; its width at half maximum is a.
Exit 1 with the failures listed.
"""
import math
import os
import sys
import tempfile

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "apps", "fluid"))
import dam_break_fronts as fronts  # noqa: E402
import dam_break_pressure as pressure  # noqa: E402

failures = []


def expect(ok, what):
    print("%s: %s" % ("ok" if ok else "FAILED", what))
    if not ok:
        failures.append(what)


def synthetic_run(directory, advance):
    """A gauge file of the 1 x 2 column (a = 1 m, g = 0.5 so that T = t) whose front is Table 2's
    curve (extended linearly at both ends) advanced by `advance` in T."""
    data = np.loadtxt(fronts.MARTIN_MOYCE)
    T = np.arange(0.0, 4.0, 1e-3)
    slope_low = (data[1, 1] - data[0, 1]) / (data[1, 0] - data[0, 0])
    slope_high = (data[-1, 1] - data[-2, 1]) / (data[-1, 0] - data[-2, 0])
    t = T + advance
    Z = np.interp(t, data[:, 0], data[:, 1])
    Z = np.where(t < data[0, 0], data[0, 1] + slope_low * (t - data[0, 0]), Z)
    Z = np.where(t > data[-1, 0], data[-1, 1] + slope_high * (t - data[-1, 0]), Z)
    path = os.path.join(directory, "synthetic.gauges.csv")
    with open(path, "w") as f:
        f.write("# fluid gauges, dam_break: length 1 m, dx 0.01 m, rho0 1000, g 0.5\n# step,t,front_x\n")
        for i, (ti, zi) in enumerate(zip(T, Z)):
            f.write("%d,%.9g,%.12g\n" % (i, ti, zi))
    return fronts.GaugeFile(path)


with tempfile.TemporaryDirectory() as directory:
    run = synthetic_run(directory, 0.2)
    best, rows = fronts.lead_table(run, [0.1, 0.2, 0.3])
    expect(abs(best - 0.2) < 1.5e-3, "best delay of Table 2 advanced by 0.2: %.4f" % best)
    _, model_mean, model_max, mean, largest, _ = rows[1]
    expect(abs(model_mean - mean) < 2e-3 and abs(model_max - largest) < 2e-3,
           "at the best delay the Table 2 errors are the model's: mean %.4f %.4f, largest %.4f %.4f" %
           (model_mean, mean, model_max, largest))
    expect(rows[0][2] < rows[1][2] < rows[2][2] and rows[0][4] < rows[1][4] < rows[2][4],
           "the largest raw error grows with the lead")
    for model in (True, False):
        lead = fronts.lead_at_raw_bound(run, 0.16, model)
        reached = fronts.lead_table(run, [lead])[1][0][2 if model else 4]
        expect(abs(reached - 0.16) < 1e-6, "inverted lead %.4f gives the raw bound: %.6f" % (lead, reached))

T_c, T_f = np.linspace(0.0, 3.0, 301), np.linspace(0.0, 3.0, 1001)  # the finer run has more rows
scale = np.linspace(0.01, 0.02, T_f.size)  # the finer front ahead by 1% at T = 0, 2% at T = 3
mean, largest = fronts.relative_change(T_c, 1.0 + T_c ** 2, T_f, (1.0 + scale) * (1.0 + T_f ** 2), (1.0, 2.3))
expect(abs(mean - 0.01 * (1 + 1.65 / 3)) < 1e-4 and abs(largest - 0.01 * (1 + 2.3 / 3)) < 1e-4,
       "relative change of a front 1%% + T/3 %% ahead over [1, 2.3]: mean %.5f (exact %.5f), largest %.5f (exact "
       "%.5f)" % (mean, 0.01 * (1 + 1.65 / 3), largest, 0.01 * (1 + 2.3 / 3)))

n, p, C = (20.0, 50.0, 100.0), 0.7, 3.0
changes = [C * (n[0] ** -p - n[1] ** -p), C * (n[1] ** -p - n[2] ** -p)]
order, following = fronts.observed_order(changes, n)
expect(abs(order - p) < 1e-6 and abs(following - C * (n[2] ** -p - (2 * n[2]) ** -p)) < 1e-9,
       "observed order %.6f (exact %g), next change %.6g" % (order, p, following))

spacing = 0.02
for offset in (0.0, 0.3 * spacing):
    grid = np.arange(0.5 * spacing, 1.0, spacing)
    x, y = np.meshgrid(grid, np.arange(0.5 * spacing, 0.5, spacing))
    x, y = x.ravel() + offset, y.ravel()
    h = np.full(x.size, 1.5 * spacing)
    for height in (0.01, 0.05):
        front = fronts.surface_front(x, y, np.full(x.size, spacing ** 2), h, height, spacing)
        edge = grid[-1] + offset + 0.5 * spacing
        expect(abs(front - edge) < 0.05 * spacing, "lattice block offset %.3f dx, height %g: front %.5f, edge %.5f" %
               (offset / spacing, height, front, edge))

P, a, d, centre = 5.0, 1e-3, pressure.experiment_interval(), 2.4
T = np.arange(2.0, 3.0, 1e-6)
spike = P * np.maximum(0.0, 1.0 - np.abs(T - centre) / a)
p2 = 0.5 * spike
points = pressure.sampled_peaks(T, spike, p2, d, integrate=False, phases=2000)
averaged = pressure.sampled_peaks(T, spike, p2, d, integrate=True, phases=2000)
for k, (median, low, high) in enumerate(points):
    scale = P * (1.0, 0.5)[k]
    expect(abs(median - scale * (1 - d / (4 * a))) < 0.01 * scale * d / a and
           abs(low - scale * (1 - 0.975 * d / (2 * a))) < 0.01 * scale * d / a and
           abs(high - scale * (1 - 0.025 * d / (2 * a))) < 0.01 * scale * d / a,
           "sensor %d point samples: median %.5f [%.5f, %.5f] against %.5f [%.5f, %.5f]" %
           (k + 1, median, low, high, scale * (1 - d / (4 * a)), scale * (1 - 0.975 * d / (2 * a)),
            scale * (1 - 0.025 * d / (2 * a))))
    expect(averaged[k][0] < median and averaged[k][2] <= scale * (1 - d / (4 * a)) + 1e-9,
           "sensor %d averaged over an interval first: median %.5f below the point samples' %.5f, at most "
           "P (1 - d / 4a) = %.5f" % (k + 1, averaged[k][0], median, scale * (1 - d / (4 * a))))
onset = centre - a * (1 - 0.1 / (0.5 * P))
width, mean = pressure.peak_shape(T, spike, onset)
expect(abs(width - a) < 1e-5, "width at half maximum %.6f (exact %g)" % (width, a))
exact = P * a / 0.1 - 0.5 * (onset - (centre - a)) * 0.1 / (0.5 * P) * P / 0.1
expect(abs(mean - exact) < 1e-3 * P, "mean over 0.1 after the onset %.6f (exact %.6f)" % (mean, exact))
sys.exit(1 if failures else 0)
