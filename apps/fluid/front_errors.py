"""The dam-break front against Martin & Moyce (1952) (martin_moyce_1952.txt) over 1 <= T <= 2.8,
for a fluid run's .series.txt or a two-column T, Z/L file (pysph_dam_break.py): the relative error
at each measured point, their mean (the fluid app's --check-dam-break measure), and the time lag
of the experiment: for each measured Z, T_experiment - T_SPH at which the SPH front reached it,
and the constant shift of the SPH curve in T that fits the points best (with its mean error).
Nothing is shifted in any check: the lag is the evidence of docs/fluid-flow.md.

    /usr/bin/python3 apps/fluid/front_errors.py db50.series.txt pysph50/front.TZ [--plot fronts.png]

With --plot, the curves (labelled by their file names) and the experiment in one figure.
"""
import os
import re
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))


def front(path):
    """T and Z / L of a run's series: its column surge_front (surge_front.hh, dx/2 included), or in
    a series written before that operator, the largest fluid x plus dx/2."""
    with open(path) as f:
        header, columns = f.readline(), f.readline()
    if "dx = " in header:  # the fluid app's series
        found = {k: float(re.search(k + r" = ([0-9.eE+-]+)", header).group(1)) for k in ("L", "dx", "g")}
        s = np.loadtxt(path)
        half_spacing = 0.0 if "surge_front" in columns else 0.5 * found["dx"]
        return s[:, 0] * np.sqrt(2 * found["g"] / found["L"]), (s[:, 1] + half_spacing) / found["L"]
    s = np.loadtxt(path)
    return s[:, 0], s[:, 1]


def plot(paths, out):
    import matplotlib
    matplotlib.use("Agg")
    import matplotlib.pyplot as plt
    fig, ax = plt.subplots(figsize=(7, 5))
    ax.axvspan(1, 2.8, color="0.9", label="compared: 1 <= T <= 2.8")
    for path in paths:
        T, Z = front(path)
        ax.plot(T, Z, label=os.path.basename(path).replace(".series.txt", ""))
    experiment = np.loadtxt(os.path.join(HERE, "martin_moyce_1952.txt"))
    ax.plot(experiment[:, 0], experiment[:, 1], "ko", label="Martin & Moyce (1952), a = 2.25 in")
    ax.set_xlim(0, 3.2), ax.set_ylim(1, 4)
    ax.set_xlabel("T = t sqrt(2 g / L)"), ax.set_ylabel("Z / L"), ax.legend(fontsize=7)
    fig.tight_layout()
    fig.savefig(out, dpi=120)


def main():
    args = sys.argv[1:]
    out = None
    if "--plot" in args:
        i = args.index("--plot")
        out = args[i + 1]
        del args[i:i + 2]
    if not args:
        sys.exit(__doc__)
    experiment = [(T, Z) for T, Z in np.loadtxt(os.path.join(HERE, "martin_moyce_1952.txt")) if 1 <= T <= 2.8]
    if out:
        plot(args, out)
    for path in args:
        T, Z = front(path)
        errors = [abs(np.interp(t, T, Z) - z) / z for t, z in experiment]
        lags = [t - np.interp(z, Z, T) for t, z in experiment]
        shifts = np.linspace(0, 0.5, 501)
        fit = [np.mean([abs(np.interp(t - s, T, Z) - z) / z for t, z in experiment]) for s in shifts]
        best = int(np.argmin(fit))
        print("%s: errors %s, mean %.2f%%; lags of the experiment %s; best shift %.3f (mean error %.2f%%)" % (
            path, " ".join("%.1f%%" % (100 * e) for e in errors), 100 * np.mean(errors),
            " ".join("%.3f" % l for l in lags), shifts[best], 100 * fit[best]))


if __name__ == "__main__":
    main()
