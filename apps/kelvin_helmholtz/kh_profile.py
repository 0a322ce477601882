"""The smooth Kelvin-Helmholtz set-up of McNally, Lyra & Passy (2012, ApJS 201, 18, eqs. 1-3) and
its mode amplitude (their eqs. 4-7), shared by kh_linear_theory.py, check_kelvin_helmholtz.py and
plot_kelvin_helmholtz.py.

In [0, 1)^2, periodic: rho = rho1 - rho_m exp((y - 1/4) / L) for y < 1/4, rho2 + rho_m exp((1/4 -
y) / L) for 1/4 <= y < 1/2, rho2 + rho_m exp((y - 3/4) / L) for 1/2 <= y < 3/4, rho1 - rho_m
exp((3/4 - y) / L) above, with rho_m = (rho1 - rho2) / 2; v_x the same with U1, U2, U_m; rho1 = 1,
rho2 = 2, U1 = 0.5, U2 = -0.5, L = 0.025, P = 2.5, gamma 5/3; v_y = 0.01 sin(4 pi x).
"""
import numpy as np

# The linear growth rate of this profile at k = 4 pi, compressible (gamma P = 25/6), from
# kh_linear_theory.py (its output 2.81930; 3.01867 incompressible; vortex sheet 5.92384).
LINEAR_GROWTH_RATE = 2.81930

RHO1, RHO2, U1, U2, SMOOTHING, PRESSURE, GAMMA, WAVE_NUMBER = 1.0, 2.0, 0.5, -0.5, 0.025, 2.5, 5.0 / 3.0, 4 * np.pi


def profile(y, outer, inner, length=SMOOTHING):
    """McNally's smoothed step between `outer` (|y - 1/2| > 1/4) and `inner` values."""
    y = np.asarray(y, dtype=float) % 1.0
    middle = (outer - inner) / 2.0
    return np.where(y < 0.25, outer - middle * np.exp((y - 0.25) / length),
                    np.where(y < 0.5, inner + middle * np.exp((0.25 - y) / length),
                             np.where(y < 0.75, inner + middle * np.exp((y - 0.75) / length),
                                      outer - middle * np.exp((0.75 - y) / length))))


def density(y):
    return profile(y, RHO1, RHO2)


def velocity_x(y):
    return profile(y, U1, U2)


def mode_amplitude(x, y, vy, volume):
    """McNally et al. (2012) eqs. 4-7: M = 2 sqrt((sum s V / sum d V)^2 + (sum c V / sum d V)^2),
    d = exp(-4 pi |y - 1/4|) below y = 1/2 and exp(-4 pi |(1 - y) - 1/4|) above, s and c = v_y
    sin(4 pi x) d and v_y cos(4 pi x) d; V the particles' volumes m / rho."""
    y = np.asarray(y) % 1.0
    weight = np.where(y < 0.5, np.exp(-4 * np.pi * np.abs(y - 0.25)), np.exp(-4 * np.pi * np.abs((1 - y) - 0.25)))
    d = np.sum(weight * volume)
    s = np.sum(vy * np.sin(4 * np.pi * x) * weight * volume)
    c = np.sum(vy * np.cos(4 * np.pi * x) * weight * volume)
    return 2.0 * np.sqrt((s / d) ** 2 + (c / d) ** 2)


def amplitude_series(path, read_step, steps):
    """(times, mode amplitudes) of the steps of an H5Part output (V = m / rho)."""
    times, amplitudes = [], []
    for step in steps:
        time, data, _ = read_step(path, step)
        times.append(time)
        amplitudes.append(mode_amplitude(data["x"] % 1.0, data["y"] % 1.0, data["vy"], data["m"] / data["rho"]))
    return np.array(times), np.array(amplitudes)


def growth_rate(times, amplitudes, window):
    """The least-squares slope of ln M over the steps with window[0] <= t <= window[1]."""
    inside = (times >= window[0] - 1e-9) & (times <= window[1] + 1e-9)
    if inside.sum() < 3:
        return float("nan")
    return float(np.polyfit(times[inside], np.log(amplitudes[inside]), 1)[0])
