#!/usr/bin/python3
# Plots of the fluid app's runs (PNG): the dam break's surge front Z/L against T = t sqrt(2g/L)
# with Martin & Moyce (1952) and the water's shape at several times; the channel flows' velocity
# profiles against their series solutions (Morris et al. 1997); the still tank's pressure profile.
#
#   /usr/bin/python3 apps/fluid/plot_fluid.py dam_break.h5part [--out dam_break.png]
import argparse
import math
import os
import sys

import matplotlib
matplotlib.use("Agg")
import matplotlib.pyplot as plt
import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "plotting"))
sys.path.insert(0, HERE)
import h5part_plot  # noqa: E402
import front_errors  # noqa: E402  (apps/fluid: the series' surge front)

PROGRAM = "plot_fluid"


def parameters(path):
    """The run's resolved parameters (root attribute 'parameters') as a dict of strings."""
    text = h5part_plot.attributes(path, PROGRAM)["parameters"]
    text = text.decode() if isinstance(text, bytes) else str(text)
    values = {}
    for line in text.splitlines():
        line = line.split("#")[0].strip()
        if "=" in line:
            key, value = line.split("=", 1)
            values[key.strip()] = value.strip().strip("\"")
    return values


def step(path, index):
    """(time, the fluid particles' x, y, vx, vy, P, rho) of Step#index."""
    time, data, _ = h5part_plot.read_step(path, index, PROGRAM)
    keep = data["kind"] == 0
    return time, {name: data[name][keep] for name in ("x", "y", "vx", "vy", "P", "rho")}


def poiseuille(y, t, L, F, nu, terms=200):
    v = F / (2 * nu) * y * (L - y)
    for n in range(terms):
        k = 2 * n + 1
        v -= 4 * F * L * L / (nu * math.pi ** 3 * k ** 3) * np.sin(k * math.pi * y / L) * math.exp(-k * k * math.pi ** 2 * nu * t / L ** 2)
    return v


def couette(y, t, L, v0, nu, terms=400):
    v = v0 * y / L
    for n in range(1, terms + 1):
        v += 2 * v0 * (-1) ** n / (n * math.pi) * np.sin(n * math.pi * y / L) * math.exp(-n * n * math.pi ** 2 * nu * t / L ** 2)
    return v


def plot_dam_break(path, p, series_path, out):
    L = float(p["length"]); g = -float(p.get("body_force_y", "-9.81"))
    fig = plt.figure(figsize=(13, 6))
    experiment = np.loadtxt(os.path.join(HERE, "martin_moyce_1952.txt"))
    ax = fig.add_subplot(1, 2, 1)
    ax.axvspan(1, 2.8, color="0.9", label="compared: 1 <= T <= 2.8")
    ax.plot(experiment[:, 0], experiment[:, 1], "ko", label="Martin & Moyce (1952), a = 2.25 in")
    if os.path.exists(series_path):
        T, Z = front_errors.front(series_path)  # the surge front (specialization/fluid/surge_front.hh)
        ax.plot(T, Z, "b-", label="SPH, dx = L/%s" % p["particles"])
    ax.set_xlim(0, 3.2); ax.set_ylim(1, 4)
    ax.set_xlabel("T = t sqrt(2 g / L)"); ax.set_ylabel("Z / L"); ax.legend(); ax.set_title("surge front")
    names = h5part_plot.step_indices(path, PROGRAM)
    picks = [names[int(i)] for i in np.linspace(0, len(names) - 1, 4)]
    for index, name in enumerate(picks):
        ax = fig.add_subplot(4, 2, 2 * index + 2)
        t, q = step(path, name)
        ax.scatter(q["x"] / L, q["y"] / L, s=0.5, c=q["P"], cmap="viridis")
        ax.set_aspect("equal"); ax.set_xlim(0, 4); ax.set_ylim(0, 2.1)
        ax.set_title("T = %.2f (colour: P)" % (t * math.sqrt(2 * g / L)), fontsize=8)
        ax.tick_params(labelsize=7)
    fig.tight_layout(); fig.savefig(out, dpi=120)


def plot_channel(path, p, out, kind):
    L = float(p["length"]); mu = float(p.get("dynamic_viscosity", "0")); rho0 = float(p.get("rho0", "1000"))
    nu = mu / rho0
    fig, ax = plt.subplots(figsize=(7, 5))
    for name in h5part_plot.step_indices(path, PROGRAM)[1:]:
        t, q = step(path, name)
        y = np.linspace(0, L, 101)
        exact = poiseuille(y, t, L, float(p["body_force_x"]), nu) if kind == "poiseuille" else couette(y, t, L, float(p["lid_velocity"]), nu)
        line, = ax.plot(exact, y / L, "-", lw=1)
        ax.plot(q["vx"], q["y"] / L, ".", ms=3, color=line.get_color(), label="t = %.2f L^2/nu" % (t * nu / L ** 2))
    ax.set_xlabel("v_x (m/s)"); ax.set_ylabel("y / L"); ax.legend(fontsize=7)
    ax.set_title("%s: SPH (dots) against the series solution (lines)" % kind)
    fig.tight_layout(); fig.savefig(out, dpi=120)


def plot_still_tank(path, p, out):
    L = float(p["length"]); g = -float(p.get("body_force_y", "-9.81")); rho0 = float(p.get("rho0", "1000"))
    _, q = step(path, h5part_plot.step_indices(path, PROGRAM)[-1])
    fig, ax = plt.subplots(figsize=(6, 5))
    ax.plot(q["P"] / (rho0 * g * L), q["y"] / L, ".", ms=2, label="SPH (last step)")
    y = np.linspace(0, L, 50)
    ax.plot((L - y) / L, y / L, "k-", label="rho0 g (H - y)")
    ax.set_xlabel("P / (rho0 g H)"); ax.set_ylabel("y / H"); ax.legend(); ax.set_title("still tank")
    fig.tight_layout(); fig.savefig(out, dpi=120)


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("file")
    parser.add_argument("--out")
    args = parser.parse_args()
    p = parameters(args.file)
    kind = p["problem"]
    out = args.out or os.path.splitext(args.file)[0] + ".png"
    series = os.path.splitext(args.file)[0] + ".series.txt"
    if kind == "dam_break":
        plot_dam_break(args.file, p, series, out)
    elif kind in ("poiseuille", "couette"):
        plot_channel(args.file, p, out, kind)
    else:
        plot_still_tank(args.file, p, out)
    print("wrote", out)


if __name__ == "__main__":
    main()
