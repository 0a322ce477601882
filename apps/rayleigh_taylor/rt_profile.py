"""The smooth Rayleigh-Taylor set-up of apps/rayleigh_taylor (Abel 2011; Hopkins 2015) and its mode
amplitude, shared by rt_linear_theory.py, check_rayleigh_taylor.py and plot_rayleigh_taylor.py.

In [0, W) x [0, H], periodic in x, walls at y = 0 and H: rho(y) = rho1 + (rho2 - rho1) / (1 +
exp(-(y - H/2) / Delta)), P(y) = P0 - g int_{H/2}^{y} rho (hydrostatic), gamma; the seed is one mode
of wavelength W, k = 2 pi / W. The keys' values are read from the output's root attributes (the
run writes its resolved parameters there), the app's defaults otherwise.
"""
import numpy as np

# The app's defaults (apps/rayleigh_taylor/rayleigh_taylor.par).
DEFAULTS = {"width": 0.5, "height": 1.0, "rho1": 1.0, "rho2": 2.0, "uniform_gravity": 0.5, "pressure": 2.5,
            "smoothing": 0.025, "gamma": 1.4}


class SetUp:
    """The set-up's numbers, from a dict of root attributes (missing keys: DEFAULTS)."""

    def __init__(self, attributes=None, **overrides):
        values = dict(DEFAULTS)
        for key in DEFAULTS:
            if attributes is not None and key in attributes:
                values[key] = float(np.asarray(attributes[key]).reshape(-1)[0])
        values.update(overrides)
        self.__dict__.update(values)
        self.interface = 0.5 * self.height
        self.wave_number = 2 * np.pi / self.width
        self.atwood = (self.rho2 - self.rho1) / (self.rho2 + self.rho1)

    def density(self, y):
        return self.rho1 + (self.rho2 - self.rho1) / (1 + np.exp(-(np.asarray(y) - self.interface) / self.smoothing))

    def density_slope(self, y):
        s = 1 / (1 + np.exp(-(np.asarray(y) - self.interface) / self.smoothing))
        return (self.rho2 - self.rho1) * s * (1 - s) / self.smoothing

    def pressure_at(self, y):
        """P0 - g int_{y_i}^{y} rho, exact (log(1 + e^z) written without overflow)."""
        z = (np.asarray(y) - self.interface) / self.smoothing
        softplus = np.maximum(z, 0) + np.log1p(np.exp(-np.abs(z)))
        column = self.rho1 * (np.asarray(y) - self.interface) + (self.rho2 - self.rho1) * self.smoothing * (
            softplus - np.log(2.0))
        return self.pressure - self.uniform_gravity * column

    def sharp_rate(self):
        """Incompressible sharp interface between walls H/2 away: sigma^2 = A k g tanh(k H / 2)
        (Chandrasekhar 1961, ch. X); tanh(2 pi) = 1 - 7e-6 here, i.e. sqrt(A k g)."""
        return float(np.sqrt(self.atwood * self.wave_number * self.uniform_gravity *
                             np.tanh(self.wave_number * self.interface)))


def mode_amplitude(x, y, vy, volume, setup):
    """A = 2 |sum V w v_y exp(-i k x)| / sum V w, w = exp(-k |y - y_i|): the Fourier amplitude of
    v_y at the seeded k, weighted towards the interface layer (as McNally et al. 2012, eqs. 4-7,
    for Kelvin-Helmholtz); V = m / rho."""
    k = setup.wave_number
    weight = np.exp(-k * np.abs(y - setup.interface)) * volume
    s = np.sum(vy * np.sin(k * x) * weight)
    c = np.sum(vy * np.cos(k * x) * weight)
    return 2.0 * np.hypot(s, c) / np.sum(weight)


def amplitude_series(path, read_step, steps, setup):
    """(times, mode amplitudes) of the steps of an H5Part output, fluid particles only."""
    times, amplitudes = [], []
    for step in steps:
        time, data, _ = read_step(path, step)
        fluid = data["kind"] == 0 if "kind" in data else np.ones(len(data["x"]), dtype=bool)
        times.append(time)
        amplitudes.append(mode_amplitude(data["x"][fluid], data["y"][fluid], data["vy"][fluid],
                                         data["m"][fluid] / data["rho"][fluid], setup))
    return np.array(times), np.array(amplitudes)


def growth_rate(times, amplitudes, window):
    """The least-squares slope of ln A over the steps with window[0] <= t <= window[1]."""
    inside = (times >= window[0] - 1e-9) & (times <= window[1] + 1e-9)
    if inside.sum() < 3:
        return float("nan")
    return float(np.polyfit(times[inside], np.log(amplitudes[inside]), 1)[0])


def growth_rate_two_modes(times, amplitudes, window):
    """The sigma of the best fit A(t) = a exp(sigma t) + b exp(-sigma t) over the steps in the
    window: the linear solution for a seed that is a mix of the growing and the decaying mode (a
    velocity seed with no displacement grows as cosh(sigma t), whose ln has the slope sigma
    tanh(sigma t), 10% short of sigma at sigma t = 1.5). For each sigma, a and b by linear least
    squares on the relative residual; sigma by a bounded scalar minimisation."""
    from scipy.optimize import minimize_scalar

    inside = (times >= window[0] - 1e-9) & (times <= window[1] + 1e-9)
    if inside.sum() < 4:
        return float("nan")
    t, a = times[inside], amplitudes[inside]

    def residual(sigma):
        basis = np.stack([np.exp(sigma * t) / a, np.exp(-sigma * t) / a], axis=1)
        coefficients, *_ = np.linalg.lstsq(basis, np.ones_like(t), rcond=None)
        return float(np.sum((basis @ coefficients - 1) ** 2))

    slope = max(growth_rate(times, amplitudes, window), 1e-3)
    best = minimize_scalar(residual, bounds=(0.2 * slope, 5 * slope), method="bounded",
                           options={"xatol": 1e-8})
    return float(best.x)
