#!/usr/bin/python3
"""TrixiParticles.jl's own dam-break runs (validation/dam_break_2d/validation_reference_wcsph_N.json,
N = 40, 80, 400 particles per H) read with this project's operators: the front (largest fluid x
plus dx/2), the wall arrival of dam_break_fronts.py (the front within dx/2 of the far wall; also
at the wall and within dx, to show how much the definition moves it), and the first impact of
dam_break_pressure.py (onset at sensor 2, the largest p within 0.5 after it) on their sensors P1
and P2, sampled every 0.01 of t sqrt(g/H) as they store them; the front's change from one file to
the next over 1 <= t sqrt(g/H) <= 2.3 (and its observed order for three files). Prints each file's model (c0, h,
EOS) from its own metadata. The JSON files are not shipped: fetch the repository.

    trixi_resolution_study.py validation_reference_wcsph_40.json validation_reference_wcsph_80.json ...
"""
import json
import math
import os
import sys

import numpy as np

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import dam_break_fronts as fronts  # noqa: E402
import dam_break_pressure as pressure  # noqa: E402

H, RHO0 = 0.6, 1000.0


def study(path):
    data = json.load(open(path))
    fluid = data["meta"]["system_data"]["fluid_1"]
    dx = fluid["particle_spacing"]
    front = data["max_x_coord_fluid_1"]
    T = np.array(front["time"]) * math.sqrt(fronts.G / H)
    x = (np.array(front["values"], float) + 0.5 * dx) / H
    tank = math.floor(5.366 * H / dx + 1e-9) * dx / H
    arrivals = [fronts.arrival(T, x, tank - offset * dx / H) for offset in (0.5, 0.0, 1.0)]
    scale = RHO0 * fronts.G * H
    series = [np.array(data["pressure_%s_fluid_1" % s]["values"], float) / scale for s in ("P1", "P2")]
    T_p = np.array(data["pressure_P1_fluid_1"]["time"]) * math.sqrt(fronts.G / H)
    onset, peak1, peak2 = pressure.first_impact(T_p, series[0], series[1])
    eos = fluid["state_equation"]
    print("%s: H/%.0f, c0 = %.2f m/s (%.1f sqrt(g H)), h = %.2f dx, EOS %s exponent %g, delta %s; wall arrival "
          "t sqrt(g/H) = %.4f (front at the wall: %.4f, within dx: %.4f); onset at P2 %.3f, first peaks P1 %.2f, "
          "P2 %.2f rho0 g H" %
          (os.path.basename(path), H / dx, fluid["sound_speed"], fluid["sound_speed"] / math.sqrt(fronts.G * H),
           fluid["smoothing_length"] / dx, eos["model"], eos["exponent"], fluid["density_diffusion"].get("delta"),
           arrivals[0], arrivals[1], arrivals[2], onset, peak1, peak2))
    return H / dx, T, x


if __name__ == "__main__":
    if len(sys.argv) < 2:
        sys.exit(__doc__)
    runs = [study(path) for path in sys.argv[1:]]
    changes = []
    for (n_c, T_c, x_c), (n_f, T_f, x_f) in zip(runs[:-1], runs[1:]):
        changes.append(fronts.relative_change(T_c, x_c, T_f, x_f, (1.0, 2.3)))
        print("front change from H/%.0f to H/%.0f over 1 <= t sqrt(g/H) <= 2.3: mean %.4f, largest %.4f" %
              (n_c, n_f, *changes[-1]))
    if len(runs) == 3:
        print("observed order of the mean change %.2f" % fronts.observed_order([c[0] for c in changes],
                                                                               [run[0] for run in runs])[0])
