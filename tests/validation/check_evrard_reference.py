#!/usr/bin/python3
"""Checks the 1D Evrard reference solver (apps/evrard/evrard_reference.py) on 200 shells.

Energy E = K + U + W conserved to round-off (the compatible scheme: the work of the forces is the change of
U and W); E0 within 1e-3 of the continuum -37/60 (W0 = -2/3, U0 = 0.05); the features of the solution at
this resolution (the 1000-shell data file gives 0.138 and 0.88): shock at r in [0.12, 0.16] at t = 0.8,
kinetic energy peaking at t in [0.83, 0.93]; the infalling gas outside the shock keeps its initial entropy
A = P / rho^gamma to 1e-4 (adiabatic; the viscosity, which acts in every compressing zone, heats the
infall by 1.3e-5 at this resolution).

    check_evrard_reference.py apps/evrard/evrard_reference.py
"""
import importlib.util
import math
import sys

import numpy as np


def main():
    spec = importlib.util.spec_from_file_location("evrard_reference", sys.argv[1])
    reference = importlib.util.module_from_spec(spec)
    spec.loader.exec_module(reference)
    shells = 200
    profile, rows, steps = reference.solve(shells, 0.8, 1.2, 0.02, 0.25, 2.0, 0.1)
    failures = []
    e0 = rows[0, 4]
    drift = np.max(np.abs(rows[:, 4] - e0)) / abs(e0)
    print(f"{shells} shells, {steps} steps: E0 = {e0:.6f}, largest |E - E0| / |E0| = {drift:.2e}")
    if drift > 1e-12:
        failures.append(f"energy drift {drift:.2e} > 1e-12")
    if abs(e0 + 37.0 / 60.0) > 1e-3:
        failures.append(f"E0 = {e0} is not -37/60 to 1e-3")
    shock = int(np.argmin(np.diff(np.log(profile[:, 5]))))
    shock_radius = 0.5 * (profile[shock, 0] + profile[shock + 1, 0])
    peak_time = rows[np.argmax(rows[:, 1]), 0]
    print(f"shock at r = {shock_radius:.4f} at t = 0.8; K peaks at t = {peak_time:.2f}")
    if not 0.12 <= shock_radius <= 0.16:
        failures.append(f"shock radius {shock_radius:.4f} not in [0.12, 0.16]")
    if not 0.83 <= peak_time <= 0.93:
        failures.append(f"K peaks at t = {peak_time} not in [0.83, 0.93]")
    # Equal-mass shells: shell j at t = 0.8 is shell j at t = 0; A0 = (gamma - 1) u0 / rho0^(2/3).
    m = np.arange(shells + 1) / shells
    r0 = np.sqrt(m)
    rho0 = (1.0 / shells) / (4.0 * math.pi / 3.0 * (r0[1:] ** 3 - r0[:-1] ** 3))
    a0 = (2.0 / 3.0) * 0.05 / rho0 ** (2.0 / 3.0)
    outside = slice(shock + 3, shells - 3)
    entropy_change = np.max(np.abs(profile[outside, 5] / a0[outside] - 1))
    print(f"largest entropy change outside the shock: {entropy_change:.2e}")
    if entropy_change > 1e-4:
        failures.append(f"the infall outside the shock changed its entropy by {entropy_change:.2e}")
    if failures:
        sys.exit("check_evrard_reference: " + "; ".join(failures))
    print("check_evrard_reference: passed")


if __name__ == "__main__":
    main()
