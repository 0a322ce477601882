#!/usr/bin/python3
"""Figures of the dam break's verification and validation (docs/fluid-flow.md), from the fluid
app's gauge files (gauge_file: the front operator's front_x and the wall gauges) and H5Part output:

    plot_dam_break_validation.py fronts --reference RUN.gauges.csv ... --martin-moyce RUN.gauges.csv ... --out F.png
        left: x_f / H against t sqrt(g/H) in the Marrone / Lobovsky geometry with TrixiParticles'
        converged H/400 run; right: Z = x_f / a against T = t sqrt(2 g / a) in the 1 x 2 column with
        Martin & Moyce's Table 2, each run also delayed by its best constant shift (stated).
    plot_dam_break_validation.py pressure RUN.gauges.csv ... --out P.png [--ringing]
        p / (rho0 g H) at gauges 1 and 2 (Lobovsky et al.'s sensors 1 and 2) against t sqrt(g/H),
        with TrixiParticles' H/400 sensors, the experiment's first peak (Lobovsky et al. 2014
        Table 2: median and 2.5-97.5% band over 100 repetitions, lobovsky_2014_pressure.txt) and
        the issue's bounds on the first impact; with --ringing each run also averaged over its
        acoustic ringing period (dam_break_pressure.py), dashed; with --repetition S1 S2 one
        repetition of the experiment (grey).
    plot_dam_break_validation.py lead RUN.gauges.csv ... --out L.png
        the largest raw error against Martin & Moyce's Table 2 as a function of the lead s of the run
        over the experiment (dam_break_fronts.py lead), with the issue's raw bound and delay band.
    plot_dam_break_validation.py shapes RUN.h5part --out S.png
        the water at every output time (colour: pressure).
"""
import argparse
import math
import os
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt  # noqa: E402
import numpy as np  # noqa: E402

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, HERE)
sys.path.insert(0, os.path.join(HERE, "..", "plotting"))
import dam_break_fronts as fronts  # noqa: E402
import dam_break_pressure as pressure  # noqa: E402


def label(run):
    text = "FleCSPH-lite dx = %s/%.0f" % ("H" if run.length > 0.1 else "a", run.length / run.dx)
    return text + (", gauge h x %g" % run.smoothing if run.smoothing != 1 else "")


def plot_fronts(reference_runs, martin_moyce_runs, out):
    fig, axes = plt.subplots(1, 2, figsize=(13, 5.5))
    ax = axes[0]
    T_ref, x_ref = fronts.reference_front()
    ax.plot(T_ref, x_ref, "k-", lw=2, label="TrixiParticles WCSPH H/400 (converged reference)")
    ax.axvspan(1.0, 2.3, color="0.92", label="compared: 1 <= t sqrt(g/H) <= 2.3")
    for path in reference_runs:
        run = fronts.GaugeFile(path)
        T = run["t"] * math.sqrt(run.g / run.length)
        if T[-1] >= 2.3:
            mean, _, arrival, _ = fronts.against_reference(run)
            text = "%s: mean error %.2f%%, wall at %.3f" % (label(run), 100 * mean, arrival)
        else:  # a run stopped early: its error over the part it covered
            mean, _, _, _ = fronts.against_reference(run, window=(1.0, T[-1] - 0.005))
            text = "%s (to %.2f): mean error %.2f%% over [1, %.2f]" % (label(run), T[-1], 100 * mean, T[-1])
        ax.plot(T, run["front_x"] / run.length, "-", label=text)
    ax.set_xlim(0, 2.6); ax.set_ylim(2, 5.5)
    ax.set_xlabel("t sqrt(g / H)"); ax.set_ylabel("x_f / H")
    ax.set_title("Marrone / Lobovsky geometry (column 2H x H, wall at 5.366 H)", fontsize=10)
    ax.legend(fontsize=8)
    ax = axes[1]
    T_exp, Z_exp = fronts.martin_moyce_points(0, 10)
    ax.plot(T_exp, Z_exp, "ko", label="Martin & Moyce (1952) Table 2, a = 2.25 in, n^2 = 2")
    ax.axvspan(1.0, 2.8, color="0.92", label="compared: 1 <= T <= 2.8 (9 points)")
    for path in martin_moyce_runs:
        run = fronts.GaugeFile(path)
        raw, shift, mean = fronts.against_martin_moyce(run)
        T, Z = fronts.martin_moyce_curve(run)
        line, = ax.plot(T, Z, "-", label="%s: raw mean error %.1f%%" % (label(run), 100 * np.mean(np.abs(raw))))
        ax.plot(T + shift, Z, "--", color=line.get_color(),
                label="  delayed by %.3f: mean error %.2f%%" % (shift, 100 * mean))
    ax.set_xlim(0, 3.2); ax.set_ylim(1, 4)
    ax.set_xlabel("T = t sqrt(2 g / a)"); ax.set_ylabel("Z = x_f / a")
    ax.set_title("Martin & Moyce column (a x 2a)", fontsize=10)
    ax.legend(fontsize=8)
    fig.tight_layout(); fig.savefig(out, dpi=120)


def plot_pressure(runs, out, t_range=(0.0, 8.0), p_max=4.5, ringing=False, repetition=None):
    fig, axes = plt.subplots(1, 2, figsize=(13, 5))
    if repetition:  # two files of t sqrt(g/H), p / (rho g H): one repetition of the experiment, sensors 1 and 2
        repetition = [np.loadtxt(path, ndmin=2) for path in repetition]
    reference = np.loadtxt(fronts.REFERENCE)
    H_ref = fronts.REFERENCE_H
    T_ref = reference[:, 0] * math.sqrt(fronts.G / H_ref)
    bounds = {1: pressure.PEAK_1, 2: pressure.PEAK_2}  # the issue's, on the first peak
    experiment = pressure.experiment_statistics()
    for k, ax in zip((1, 2), axes):
        ax.plot(T_ref, reference[:, 1 + k] / (1000 * fronts.G * H_ref), "k-", lw=1.5,
                label="TrixiParticles WCSPH H/400 (H = 0.6 m)")
        if repetition:
            ax.plot(repetition[k - 1][:, 0], repetition[k - 1][:, 1], "-", color="0.5", lw=1.5,
                    label="experiment, one repetition (20 kHz, H = 0.3 m)")
        for path in runs:
            run = fronts.GaugeFile(path)
            T = run["t"] * math.sqrt(run.g / run.length)
            scale = run.rho0 * run.g * run.length
            line, = ax.plot(T, run["p_%d" % k] / scale, "-", lw=1, label="%s (H = %g m)" % (label(run), run.length))
            if ringing:
                onset, _, _ = pressure.first_impact(T, run["p_1"] / scale, run["p_2"] / scale)
                period = pressure.ringing_period(T, (run["p_1"] / scale, run["p_2"] / scale), onset)
                ax.plot(T, pressure.running_mean(T, run["p_%d" % k] / scale, period), "--", color=line.get_color(),
                        lw=1.5, label="  averaged over its ringing period %.4f" % period)
        _, median, low, high = experiment[k]
        ax.axhspan(low, high, color="tab:red", alpha=0.15,
                   label="first peak, Lobovsky et al. 2014 (H = 0.3 m): 2.5-97.5%% [%.2f, %.2f]" % (low, high))
        ax.axhline(median, color="tab:red", ls="--", lw=1, label="  their median %.2f" % median)
        for bound in bounds[k]:
            ax.axhline(bound, color="tab:red", ls=":", lw=1)
        ax.plot([], [], color="tab:red", ls=":", lw=1, label="first peak: the issue's bounds [%g, %g]" % bounds[k])
        if k == 2:
            ax.axvspan(*pressure.ONSET, color="tab:blue", alpha=0.12, label="onset p > 0.1 rho g H: issue's band")
        ax.set_xlim(*t_range); ax.set_ylim(-0.2, p_max)
        ax.set_xlabel("t sqrt(g / H)"); ax.set_ylabel("p / (rho0 g H)")
        ax.set_title("sensor %d (downstream wall, centre %g H)" % (k, 0.01 if k == 1 else 0.05), fontsize=10)
        ax.legend(fontsize=8)
    fig.tight_layout(); fig.savefig(out, dpi=120)


def plot_lead(runs, out, bound=0.16):
    """The largest raw error against Martin & Moyce as a function of the run's lead s over the
    experiment (dam_break_fronts.py lead): each run's curve as if its best delay were s."""
    fig, ax = plt.subplots(figsize=(7.5, 5))
    leads = np.linspace(0.0, 0.35, 71)
    ax.axvspan(0.10, 0.30, color="0.92", label="the issue's band for the delay, [0.10, 0.30]")
    ax.axvspan(0.17, 0.25, color="tab:green", alpha=0.12, label="published leads of converged codes, 0.17-0.25")
    ax.axhline(100 * bound, color="tab:red", ls=":", label="the issue's raw bound %g%%" % (100 * bound))
    for path in runs:
        run = fronts.GaugeFile(path)
        best, rows = fronts.lead_table(run, leads)
        rows = np.array(rows)
        line, = ax.plot(leads, 100 * rows[:, 4], "-", label="%s, against Table 2" % label(run))
        ax.plot(leads, 100 * rows[:, 2], "--", color=line.get_color(), lw=1,
                label="  against its own curve delayed by s (no scatter)")
        ax.plot([best], [100 * np.interp(best, leads, rows[:, 4])], "o", color=line.get_color(),
                label="  its own lead %.3f" % best)
    ax.set_xlim(0, 0.35); ax.set_ylim(0, 25)
    ax.set_xlabel("lead s of the run over the experiment (T = t sqrt(2 g / a))")
    ax.set_ylabel("largest raw error over 1 <= T <= 2.8 (%)")
    ax.set_title("Martin & Moyce column: the raw error a lead implies", fontsize=10)
    ax.legend(fontsize=7, loc="upper left")
    fig.tight_layout(); fig.savefig(out, dpi=120)


def plot_shapes(path, out):
    import h5part_plot
    names = h5part_plot.step_indices(path, "plot_dam_break_validation")
    picks = names[:: max(1, len(names) // 6)][:6]
    fig, axes = plt.subplots(len(picks), 1, figsize=(9, 2.0 * len(picks)))
    text = h5part_plot.attributes(path, "plot_dam_break_validation")["parameters"]
    text = text.decode() if isinstance(text, bytes) else str(text)
    pairs = (line.split("#")[0].split("=", 1) for line in text.splitlines() if "=" in line.split("#")[0])
    values = {key.strip(): value.strip() for key, value in pairs}
    H = float(values["length"])
    for ax, name in zip(np.atleast_1d(axes), picks):
        t, data, _ = h5part_plot.read_step(path, name, "plot_dam_break_validation")
        fluid = data["kind"] == 0
        ax.scatter(data["x"][fluid] / H, data["y"][fluid] / H, s=0.3, c=data["P"][fluid], cmap="viridis")
        ax.scatter(data["x"][~fluid] / H, data["y"][~fluid] / H, s=0.3, c="0.6")
        ax.set_aspect("equal"); ax.set_xlim(-0.2, 5.6); ax.set_ylim(-0.2, 2.0)
        ax.set_title("t sqrt(g/H) = %.2f (colour: P)" % (t * math.sqrt(9.81 / H)), fontsize=8)
        ax.tick_params(labelsize=7)
    fig.tight_layout(); fig.savefig(out, dpi=120)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("figure", choices=["fronts", "pressure", "lead", "shapes"])
    parser.add_argument("files", nargs="*")
    parser.add_argument("--reference", nargs="*", default=[])
    parser.add_argument("--martin-moyce", nargs="*", default=[])
    parser.add_argument("--out", required=True)
    parser.add_argument("--t-range", nargs=2, type=float, default=[0.0, 8.0], help="pressure: t sqrt(g/H) shown")
    parser.add_argument("--p-max", type=float, default=4.5, help="pressure: the top of the p / (rho0 g H) axis")
    parser.add_argument("--ringing", action="store_true", help="pressure: also each run averaged over its ringing")
    parser.add_argument("--repetition", nargs=2, metavar=("S1", "S2"),
                        help="pressure: one repetition of the experiment, t sqrt(g/H) and p / (rho g H) at sensors 1 "
                             "and 2 (docs/fluid-flow.md: TNL-SPH's copy of Lobovsky et al.'s Fig. 18 series)")
    args = parser.parse_args()
    if args.figure == "fronts":
        plot_fronts(args.reference, args.martin_moyce, args.out)
    elif args.figure == "pressure":
        plot_pressure(args.files, args.out, args.t_range, args.p_max, args.ringing, args.repetition)
    elif args.figure == "lead":
        plot_lead(args.files, args.out)
    else:
        plot_shapes(args.files[0], args.out)
    print("wrote", args.out)


if __name__ == "__main__":
    main()
