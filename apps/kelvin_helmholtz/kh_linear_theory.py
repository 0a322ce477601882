"""The linear growth rate of McNally et al.'s (2012) smooth Kelvin-Helmholtz profile at k = 4 pi,
computed here (the issue allows it as the reference): the eigenvalue c of the compressible
Rayleigh equation for the pressure perturbation p(y) exp(i k (x - c t)) of a parallel flow U(y),
rho(y) at uniform pressure P (e.g. Blumen, Drazin & Billings 1975, J. Fluid Mech. 71, 305):

    (p' / (rho (U - c)^2))' = k^2 (1 / (rho (U - c)^2) - 1 / (gamma P)) p,

for one shear layer (at y = 1/4; the other, 1/2 away, couples by exp(-2 pi) = 0.2%), with p
decaying as exp(-kappa |y|) away from it, kappa^2 = k^2 (1 - rho (U - c)^2 / (gamma P)). Found by
shooting and Newton on c; the growth rate is sigma = k Im(c). gamma P -> infinity gives the
incompressible rate; L -> 0 the vortex sheet's k dU sqrt(rho1 rho2) / (rho1 + rho2).

    kh_linear_theory.py [--json FILE] [--michalke]

--michalke checks the solver on the classical case first: the homogeneous tanh layer U = -(1/2)
tanh(y / delta) at k delta = 0.4446 grows at 0.1897 (U / delta) (Michalke 1964, J. Fluid Mech. 19,
543); measured 3.79404 against 3.794 for delta = 0.025.
"""
import argparse
import json
import os
import sys

import numpy as np
from scipy.integrate import solve_ivp

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import kh_profile as kh  # noqa: E402


def mismatch(c, k, sound, length, span):
    """The top boundary condition's residual p' + kappa p after shooting from the bottom."""
    inverse_gp = 0.0 if sound is None else 1.0 / sound

    def rho(y):
        return kh.profile(y, kh.RHO1, kh.RHO2, length)

    def u(y):
        return kh.profile(y, kh.U1, kh.U2, length)

    def kappa(rho_value, u_value):
        value = np.sqrt(k * k * (1 - rho_value * (u_value - c) ** 2 * inverse_gp) + 0j)
        return value if value.real > 0 else -value

    bottom, top = 0.25 - span, 0.25 + span
    a = rho(bottom) * (u(bottom) - c) ** 2
    start = kappa(rho(bottom), u(bottom))
    # p = exp(kappa (y - bottom)): p' = kappa p, w = p' / a.

    def rhs(y, state):
        p, w = state[0] + 1j * state[1], state[2] + 1j * state[3]
        coefficient = rho(y) * (u(y) - c) ** 2
        dp = coefficient * w
        dw = k * k * (1 / coefficient - inverse_gp) * p
        return [dp.real, dp.imag, dw.real, dw.imag]

    w0 = start / a
    solution = solve_ivp(rhs, (bottom, top), [1.0, 0.0, w0.real, w0.imag], rtol=1e-10, atol=1e-12, method="DOP853")
    p = solution.y[0, -1] + 1j * solution.y[1, -1]
    w = solution.y[2, -1] + 1j * solution.y[3, -1]
    coefficient = rho(top) * (u(top) - c) ** 2
    # Scaled by the growth of the bottom solution, not by p: analytic in c, without poles.
    residual = (coefficient * w + kappa(rho(top), u(top)) * p) / k * np.exp(-start * (top - bottom))
    return residual


def growth_rate(k=kh.WAVE_NUMBER, sound=kh.GAMMA * kh.PRESSURE, length=kh.SMOOTHING, span=0.24):
    """(sigma, c) for a layer of smoothing `length`; the shooting spans +-span about it (far field
    exact when span >> length: exp(-span / length) of the profile is left)."""
    sheet = (kh.RHO1 * kh.U1 + kh.RHO2 * kh.U2) / (kh.RHO1 + kh.RHO2) + 1j * np.sqrt(kh.RHO1 * kh.RHO2) * abs(
        kh.U1 - kh.U2) / (kh.RHO1 + kh.RHO2)

    # Continuation from a nearly sharp layer (L / 16, close to the vortex sheet) to L, each step a
    # complex Newton iteration (the residual is analytic in c; its derivative by a difference).
    c = sheet.real + 0.95j * sheet.imag
    for step in np.geomspace(length / 16, length, 33):
        reach = min(span, max(0.05, span * step / length))
        for _ in range(50):
            residual = mismatch(c, k, sound, step, reach)
            derivative = (mismatch(c + 1e-7, k, sound, step, reach) - residual) / 1e-7
            change = residual / derivative
            c -= change
            if abs(change) < 1e-11:
                break
        else:
            sys.exit("kh_linear_theory: Newton did not converge at L = %g" % step)
        if c.imag <= 0:
            sys.exit("kh_linear_theory: no growing eigenvalue at L = %g" % step)
    return k * c.imag, c


def michalke_check():
    """Michalke's (1964) homogeneous tanh layer through the same solver; exits 1 beyond 1e-3."""
    sharp = kh.profile

    def tanh_layer(y, outer, inner, length=kh.SMOOTHING):
        if (outer, inner) == (kh.RHO1, kh.RHO2):
            return np.ones_like(np.asarray(y, dtype=float))
        return -0.5 * np.tanh((np.asarray(y, dtype=float) - 0.25) / length)

    kh.profile = tanh_layer
    try:
        rate, _ = growth_rate(k=0.4446 / kh.SMOOTHING, sound=None)
    finally:
        kh.profile = sharp
    expected = 0.1897 * 0.5 / kh.SMOOTHING
    print("Michalke (1964) tanh layer, k delta = 0.4446: growth rate %.5f, published %.4f" % (rate, expected))
    if abs(rate / expected - 1) > 1e-3:
        sys.exit(1)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--json")
    parser.add_argument("--michalke", action="store_true", help="check the solver on Michalke's tanh layer")
    arguments = parser.parse_args()
    if arguments.michalke:
        michalke_check()
    compressible, c = growth_rate()
    incompressible, _ = growth_rate(sound=None)
    sheet = kh.WAVE_NUMBER * abs(kh.U1 - kh.U2) * np.sqrt(kh.RHO1 * kh.RHO2) / (kh.RHO1 + kh.RHO2)
    wide_span, _ = growth_rate(span=0.2)
    result = {"growth_rate": compressible, "phase_speed": c.real, "incompressible_growth_rate": incompressible,
              "vortex_sheet_growth_rate": sheet, "growth_rate_span_0.2": wide_span}
    print("McNally et al. (2012) profile, k = 4 pi: linear growth rate %.5f (compressible, gamma P = %.4g; phase "
          "speed %.5f), %.5f incompressible, vortex sheet %.5f; shooting span 0.24 vs 0.2: %.2e apart" %
          (compressible, kh.GAMMA * kh.PRESSURE, c.real, incompressible, sheet, abs(compressible - wide_span)))
    if arguments.json:
        with open(arguments.json, "w") as out:
            json.dump(result, out, indent=1)


if __name__ == "__main__":
    main()
