#!/usr/bin/python3
"""Reference solution of the Evrard (1988) collapse: 1D spherical Lagrangian hydrodynamics with self-gravity.

An independent check of the SPH app (no code shared with it): von Neumann & Richtmyer (1950) staggered
Lagrangian scheme on equal-mass shells, quadratic plus linear artificial viscosity, ideal gas, gravity of the
enclosed mass, the compatible (energy-conserving) predictor-corrector of Caramana et al. (1998, J. Comput. Phys.
146, 227): K + U + W is conserved to round-off and the iteration tolerance. Initial state (Evrard 1988, MNRAS 235, 911): M = R = G = 1,
rho = M / (2 pi R^2 r) inside R, u = 0.05 G M / R, at rest, gamma = 5/3; then
W0 = -2/3 G M^2 / R, U0 = 0.05, E0 = -37/60 = -0.616667.

Writes the radial profile at --time (r, rho, v, P, u, A = P / rho^gamma per shell) and the energies
K, U, W, E against t (every --energy-every) as text files numpy.loadtxt reads:

    evrard_reference.py [--shells 1000] [--time 0.8] [--end 3] \\
        [--profile apps/evrard/evrard_reference_t0.8.txt] [--energies apps/evrard/evrard_reference_energies.txt]
"""
import argparse
import math
import sys

import numpy as np

GAMMA = 5.0 / 3.0


class Shells:
    """N equal-mass shells: interface radii r[0..N] (r[0] = 0 fixed), velocities u[0..N], zone energies e[0..N-1]."""

    def __init__(self, shells, u0, quadratic, linear):
        self.n = shells
        self.dm = np.full(shells, 1.0 / shells)                       # zone masses (M = 1)
        self.m = np.concatenate(([0.0], np.cumsum(self.dm)))           # mass inside each interface
        self.m[-1] = 1.0
        self.r = np.sqrt(self.m)                                       # M(<r) = r^2 for rho = 1 / (2 pi r)
        self.node_mass = np.empty(shells + 1)                          # half of each neighbouring zone
        self.node_mass[0] = 0.5 * self.dm[0]
        self.node_mass[1:-1] = 0.5 * (self.dm[:-1] + self.dm[1:])
        self.node_mass[-1] = 0.5 * self.dm[-1]
        self.u = np.zeros(shells + 1)
        self.e = np.full(shells, u0)
        self.quadratic, self.linear = quadratic, linear

    def volumes(self, r):
        return (4.0 * math.pi / 3.0) * (r[1:] ** 3 - r[:-1] ** 3)

    def density(self, r=None):
        return self.dm / self.volumes(self.r if r is None else r)

    def hydro_forces(self, r, e, u):
        """Force on each interface from the pressure and viscosity of its two zones (none outside the sphere)."""
        rho = self.density(r)
        stress = np.concatenate(((GAMMA - 1.0) * rho * e + self.viscosity(u, rho, e), [0.0]))
        force = np.zeros(self.n + 1)
        force[1:] = -4.0 * math.pi * r[1:] ** 2 * (stress[1:] - stress[:-1])
        return force, stress[:-1]

    def viscosity(self, u, rho, e):
        """von Neumann-Richtmyer q = rho (c2 du^2 + c1 c_s |du|) in compressing zones, else 0."""
        du = u[1:] - u[:-1]
        sound = np.sqrt(GAMMA * (GAMMA - 1.0) * np.maximum(e, 0.0))
        return np.where(du < 0.0, rho * (self.quadratic * du * du + self.linear * sound * np.abs(du)), 0.0)

    def time_step(self, courant):
        dr = self.r[1:] - self.r[:-1]
        sound = np.sqrt(GAMMA * (GAMMA - 1.0) * self.e)
        du = np.abs(self.u[1:] - self.u[:-1])
        hydro = np.min(dr / (sound + 2.0 * self.quadratic * du + 1e-30))
        # The free-fall time of the innermost shells bounds the step too (cold or slow gas).
        gravity = np.min(np.sqrt(self.r[1:] ** 3 / self.m[1:]))
        return courant * min(hydro, 0.1 * gravity)

    def step(self, dt):
        """One step of the compatible predictor-corrector scheme (Caramana, Burton, Shashkov & Whalen 1998):
        forces at the half step; the zones' internal energy changes by minus the work of their forces on the
        interfaces moving at the step's mean velocity, so pressure and viscosity conserve K + U to round-off.
        Gravity on interface i is -G m_i dm_i / (r_i^n r_i^{n+1}), whose work over the step is exactly the change
        of W = -sum G m_i dm_i / r_i; that makes the step implicit in r^{n+1}, solved by fixed-point iteration."""
        r0, u0, e0 = self.r, self.u, self.e
        # Predictor: the half-step state with the old velocities.
        r_half = r0 + 0.5 * dt * u0
        force0, stress0 = self.hydro_forces(r0, e0, u0)
        area0 = 4.0 * math.pi * r0 ** 2
        e_half = e0 - 0.5 * dt * stress0 * (area0[1:] * u0[1:] - area0[:-1] * u0[:-1]) / self.dm
        force, stress = self.hydro_forces(r_half, e_half, u0)
        area = 4.0 * math.pi * r_half ** 2
        # Corrector, iterated for the implicit gravity term.
        r1 = r_half + 0.5 * dt * u0
        for _ in range(50):
            total = force.copy()
            total[1:] -= self.m[1:] * self.node_mass[1:] / (r0[1:] * r1[1:])
            u1 = u0 + dt * total / self.node_mass
            u1[0] = 0.0
            mean = 0.5 * (u0 + u1)
            r_next = r0 + dt * mean
            converged = np.max(np.abs(r_next - r1) / (r_next + 1e-300)) < 1e-15
            r1 = r_next
            if converged:
                break
        if np.any(r1[1:] <= r1[:-1]):
            raise RuntimeError("evrard_reference: shells crossed (time step too long)")
        self.e = e0 - dt * stress * (area[1:] * mean[1:] - area[:-1] * mean[:-1]) / self.dm
        self.r, self.u = r1, u1

    def energies(self):
        """K, U and W = -sum G m_i dm_i / r_i of the nodes (the potential whose gradient the scheme's gravity is)."""
        kinetic = 0.5 * np.sum(self.node_mass * self.u ** 2)
        internal = np.sum(self.dm * self.e)
        potential = -np.sum(self.m[1:] * self.node_mass[1:] / self.r[1:])
        return kinetic, internal, potential

    def profile(self):
        """Per shell: radius of the volume midpoint, rho, v (mean of its interfaces), P, u, A = P / rho^gamma."""
        rho = self.density()
        pressure = (GAMMA - 1.0) * rho * self.e
        radius = (0.5 * (self.r[1:] ** 3 + self.r[:-1] ** 3)) ** (1.0 / 3.0)
        velocity = 0.5 * (self.u[1:] + self.u[:-1])
        return np.column_stack((radius, rho, velocity, pressure, self.e, pressure / rho ** GAMMA))


def solve(shells, profile_time, end_time, energy_every, courant, quadratic, linear, u0=0.05):
    """Runs to end_time; returns (profile at profile_time, energy rows [t, K, U, W, E], steps, E0 of the shells)."""
    gas = Shells(shells, u0, quadratic, linear)
    times = [k * energy_every for k in range(int(round(end_time / energy_every)) + 1)]
    stops = sorted(set(times + [profile_time]))
    rows, profile, t, steps, dt_last = [], None, 0.0, 0, None
    for stop in stops:
        while t < stop - 1e-14:
            dt = gas.time_step(courant)
            if dt_last is not None:
                dt = min(dt, 1.2 * dt_last)              # no sudden growth of the step
            dt_last = dt
            dt = min(dt, stop - t)
            gas.step(dt)
            t = stop if stop - t - dt < 1e-14 else t + dt
            steps += 1
        if abs(stop - profile_time) < 1e-14:
            profile = gas.profile()
        if any(abs(stop - x) < 1e-14 for x in times):
            k, u, w = gas.energies()
            rows.append((stop, k, u, w, k + u + w))
    return profile, np.array(rows), steps


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("--shells", type=int, default=1000, help="equal-mass Lagrangian shells")
    parser.add_argument("--time", type=float, default=0.8, help="time of the profile")
    parser.add_argument("--end", type=float, default=3.0, help="end time of the energy history")
    parser.add_argument("--energy-every", type=float, default=0.01, help="interval of the energy rows")
    parser.add_argument("--courant", type=float, default=0.25)
    parser.add_argument("--quadratic", type=float, default=2.0, help="c2 of q = rho (c2 du^2 + c1 c_s |du|)")
    parser.add_argument("--linear", type=float, default=0.1, help="c1 of q")
    parser.add_argument("--profile", default="evrard_reference_t0.8.txt", help="profile file to write")
    parser.add_argument("--energies", default="evrard_reference_energies.txt", help="energy file to write")
    args = parser.parse_args()
    if args.shells < 10 or not (0 < args.time <= args.end) or args.energy_every <= 0:
        sys.exit("evrard_reference: need --shells >= 10, 0 < --time <= --end and --energy-every > 0")

    profile, rows, steps = solve(args.shells, args.time, args.end, args.energy_every, args.courant, args.quadratic,
                                 args.linear)
    e0 = rows[0, 4]
    drift = np.max(np.abs(rows[:, 4] - e0)) / abs(e0)
    peak = rows[np.argmax(rows[:, 1])]
    # The shock: the steepest rise of the entropy A outwards (A jumps across it, is flat in the cold infall).
    log_a = np.log(profile[:, 5])
    shock = int(np.argmin(np.diff(log_a)))
    shock_radius = 0.5 * (profile[shock, 0] + profile[shock + 1, 0])
    parameters = (f"{args.shells} equal-mass shells, courant {args.courant}, viscosity c2 {args.quadratic} "
                  f"c1 {args.linear}, {steps} steps")
    summary = (f"E0 = {e0:.6f} (continuum -37/60 = {-37 / 60:.6f}); max |E - E0| / |E0| to t = {args.end}: "
               f"{drift:.2e}; K peaks at t = {peak[0]:.2f} (K = {peak[1]:.4f}); shock at r = {shock_radius:.4f} "
               f"at t = {args.time}")
    header = ("Evrard collapse, 1D Lagrangian reference (apps/evrard/evrard_reference.py), M = R = G = 1, "
              f"gamma 5/3, u0 = 0.05; {parameters}\n{summary}\n")
    np.savetxt(args.profile, profile, fmt="%.6e",
               header=header + f"profile at t = {args.time}; columns: r rho v P u A=P/rho^gamma")
    np.savetxt(args.energies, rows, fmt="%.7e", header=header + "columns: t K U W E=K+U+W")
    print(f"evrard_reference: {parameters}\n{summary}\nwrote {args.profile} and {args.energies}")


if __name__ == "__main__":
    main()
