"""The Noh (1987) implosion's exact solution and the measures of a run against it, shared by
plot_noh.py and tests/validation/check_noh.py.

Cold gas of density rho0 moving at speed w towards the centre (D = 2: a line, D = 3: a point):
the shock leaves the centre at speed w (gamma - 1) / 2, so r_s = w t (gamma - 1) / 2; behind it
the gas is at rest with density rho0 ((gamma + 1) / (gamma - 1))^D (16 in 2D, 64 in 3D for
gamma 5/3) and u = w^2 / 2; ahead of it rho0 (1 + w t / r)^(D - 1) and v = -w (Noh 1987, sec. 4; Liska &
Wendroff 2003, SIAM J. Sci. Comput. 25, 995, sec. 4.5).
"""
import numpy as np


def exact(r, time, dimension, gamma=5.0 / 3.0, rho0=1.0, speed=1.0):
    """(rho, v_r, u) of the exact solution at radii r."""
    shock = shock_radius(time, gamma, speed)
    inside = r < shock
    safe = np.where(r > 0, r, 1.0)
    rho = np.where(inside, post_shock_density(dimension, gamma, rho0),
                   rho0 * (1.0 + speed * time / safe) ** (dimension - 1))
    v = np.where(inside, 0.0, -speed)
    u = np.where(inside, 0.5 * speed * speed, 0.0)
    return rho, v, u


def shock_radius(time, gamma=5.0 / 3.0, speed=1.0):
    return speed * time * (gamma - 1.0) / 2.0


def post_shock_density(dimension, gamma=5.0 / 3.0, rho0=1.0):
    return rho0 * ((gamma + 1.0) / (gamma - 1.0)) ** dimension


def radii(data, dimension):
    position = np.stack([data[k] for k in ("x", "y", "z")[:dimension]], axis=1)
    velocity = np.stack([data[k] for k in ("vx", "vy", "vz")[:dimension]], axis=1)
    r = np.sqrt(np.einsum("ij,ij->i", position, position))
    v_r = np.einsum("ij,ij->i", position, velocity) / np.where(r > 0, r, 1.0)
    return r, v_r


def shell_means(r, values, width, count):
    shell = np.floor(r / width).astype(int)
    keep = shell < count
    sums = np.bincount(shell[keep], weights=values[keep], minlength=count)
    number = np.bincount(shell[keep], minlength=count)
    return (np.arange(count) + 0.5) * width, np.where(number > 0, sums / np.maximum(number, 1), np.nan), number


def measure(r, rho, u, time, dimension, gamma=5.0 / 3.0, rho0=1.0, speed=1.0):
    """The run's shock radius, post-shock density and wall heating against the exact solution.

    shock: the outermost radius where the mean density in shells of width r_s / 40 crosses half
    way between the post-shock density and the exact pre-shock density at r_s (10 in 2D, 40 in
    3D), interpolated linearly; plateau: the mean density of the particles at 0.4 r_s < r <
    0.85 r_s (beyond the wall-heated centre, inside the smoothed shock); wall heating: the mean
    density and u of the particles within 0.1 r_s of the centre (exact: the plateau's and w^2/2).
    """
    exact_shock = shock_radius(time, gamma, speed)
    rho_post = post_shock_density(dimension, gamma, rho0)
    rho_pre = rho0 * (1.0 + speed * time / exact_shock) ** (dimension - 1)
    half = 0.5 * (rho_post + rho_pre)
    width = exact_shock / 40.0
    centres, means, _ = shell_means(r, rho, width, 80)
    shock = float("nan")
    for i in range(len(centres) - 2, -1, -1):  # from outside inwards: the first shell above half height
        if np.isfinite(means[i]) and means[i] >= half and np.isfinite(means[i + 1]) and means[i + 1] < half:
            shock = centres[i] + width * (means[i] - half) / (means[i] - means[i + 1])
            break
    plateau = (r > 0.4 * exact_shock) & (r < 0.85 * exact_shock)
    centre = r < 0.1 * exact_shock
    return {
        "time": time,
        "shock_radius": shock,
        "exact_shock_radius": exact_shock,
        "shock_error": (shock - exact_shock) / exact_shock,
        "plateau_density": float(rho[plateau].mean()) if plateau.any() else float("nan"),
        "plateau_scatter": float(rho[plateau].std() / rho[plateau].mean()) if plateau.any() else float("nan"),
        "exact_density": rho_post,
        "density_error": float(rho[plateau].mean() / rho_post - 1.0) if plateau.any() else float("nan"),
        "centre_density": float(rho[centre].mean()) if centre.any() else float("nan"),
        "centre_u": float(u[centre].mean()) if centre.any() else float("nan"),
        "exact_u": 0.5 * speed * speed,
        "centre_particles": int(centre.sum()),
    }


def summary(m, dimension):
    return (f"Noh {dimension}D at t = {m['time']:.6g}: shock at r = {m['shock_radius']:.5f} (exact "
            f"{m['exact_shock_radius']:.5f}, relative error {m['shock_error']:+.4f}); post-shock density "
            f"{m['plateau_density']:.4f} at 0.4-0.85 r_s (exact {m['exact_density']:.4g}, relative error "
            f"{m['density_error']:+.4f}, scatter {m['plateau_scatter']:.4f}); wall heating: within 0.1 r_s "
            f"({m['centre_particles']} particles) density {m['centre_density']:.4f} "
            f"({m['centre_density'] / m['exact_density']:.3f} of exact), u {m['centre_u']:.4f} "
            f"({m['centre_u'] / m['exact_u']:.3f} of exact {m['exact_u']:.3g})")
