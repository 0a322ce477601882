#!/usr/bin/python3
"""Initial conditions for SWIFT of the 3D Sedov blast that bench_sedov runs (apps/sedov).

  /usr/bin/python3 make_sedov_ics.py N OUTPUT.hdf5 [--eta 1.42]

Writes N^3 particles on the cubic lattice (i + 0.5) / N of the periodic box [0, 1)^3 (ours is
[-0.5, 0.5)^3: the same lattice shifted by 0.5), as apps/sedov/sedov_problem.hh's create_lattice:
  * mass m = rho0 / S(h) and h = eta (m / rho0)^(1/3) at their fixed point, S(h) the cubic spline's
    sum over the lattice (sph::density_consistent_particle), so the SPH density is rho0 = 1;
  * u = P / ((gamma - 1) rho0) with P = 1e-6, gamma = 5/3, plus the blast: each particle gets
    E W(|x - centre|, h) / (m sum_j W(|x_j - centre|, h)) per unit mass, E = 1 (the deposit
    spread by the kernel of support 2 h around the centre of the box);
  * velocity 0.
Our kernel reaches 2 h; SWIFT's cubic spline reaches kernel_gamma h_swift with kernel_gamma =
1.825742 (3D), so the file holds h_swift = 2 h / kernel_gamma: the same support, and with
SPH:resolution_eta = 2 eta / kernel_gamma SWIFT's h is already at its fixed point.
Prints one line: particles, mass, our h, SWIFT's h, the support, the deposit's weight sum, and
our first Courant step 0.3 h / (2 c_max) as 'courant_dt DT' (run_side_by_side.sh gives SWIFT that dt).
"""
import argparse
import math

import h5py
import numpy as np

KERNEL_GAMMA = 1.825742  # SWIFT's cubic spline in 3D: support / h
GAMMA = 5.0 / 3.0
RHO0 = 1.0
PRESSURE = 1e-6
ENERGY = 1.0
SIDE = 1.0


def spline(q):
    """Our cubic spline's shape f(q), support q < 2 (the normalisation cancels below)."""
    a = np.maximum(2.0 - q, 0.0)
    b = np.maximum(1.0 - q, 0.0)
    return 0.25 * (a ** 3 - 4.0 * b ** 3) / math.pi


def kernel(r, h):
    return spline(r / h) / h ** 3


def lattice_sum(h, spacing):
    """sum_j W(|x_j - x_i|, h) over the cubic lattice around one of its sites (itself included)."""
    n = int(math.ceil(2.0 * h / spacing)) + 1
    k = np.arange(-n, n + 1) * spacing
    x, y, z = np.meshgrid(k, k, k, indexing="ij")
    return float(np.sum(kernel(np.sqrt(x * x + y * y + z * z), h)))


def density_consistent(eta, spacing):
    volume = spacing ** 3
    mass, h = RHO0 * volume, eta * spacing
    for _ in range(100):
        mass = RHO0 / lattice_sum(h, spacing)
        new_h = eta * (mass / RHO0) ** (1.0 / 3.0)
        converged = abs(new_h - h) <= 1e-15 * h
        h = new_h
        if converged:
            break
    return mass, h


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("per_side", type=int, help="lattice particles per side (N^3 particles)")
    parser.add_argument("output", help="HDF5 file to write")
    parser.add_argument("--eta", type=float, default=1.42, help="our h = eta (m/rho)^(1/3) (bench_sedov: 1.42)")
    args = parser.parse_args()
    n = args.per_side
    if n < 4:
        parser.error("per_side must be at least 4")
    total = n ** 3
    spacing = SIDE / n
    mass, h = density_consistent(args.eta, spacing)

    # Sites in our order (x fastest), positions in [0, 1): (i + 0.5) spacing.
    index = np.arange(total, dtype=np.int64)
    ijk = np.stack([index % n, (index // n) % n, index // (n * n)], axis=1)
    positions = (ijk + 0.5) * spacing
    centre = 0.5 * SIDE
    radius = np.sqrt(np.sum((positions - centre) ** 2, axis=1))
    weights = kernel(radius, h)
    weight_sum = float(np.sum(weights))
    u_background = PRESSURE / ((GAMMA - 1.0) * RHO0)
    u = u_background + ENERGY * weights / (mass * weight_sum)

    h_swift = 2.0 * h / KERNEL_GAMMA
    # Our first Courant step, courant h / (2 c_max) (v_signal = c_a + c_b at rest), courant 0.3.
    sound_speed = math.sqrt(GAMMA * (GAMMA - 1.0) * float(u.max()))
    courant_dt = 0.3 * h / (2.0 * sound_speed)
    with h5py.File(args.output, "w") as f:
        header = f.create_group("Header")
        counts = np.array([total, 0, 0, 0, 0, 0, 0], dtype=np.int64)  # swift_type_count = 7
        header.attrs["BoxSize"] = np.array([SIDE, SIDE, SIDE], dtype=np.float64)
        header.attrs["NumPart_ThisFile"] = counts
        header.attrs["NumPart_Total"] = counts % (1 << 32)
        header.attrs["NumPart_Total_HighWord"] = counts >> 32
        header.attrs["MassTable"] = np.zeros(7, dtype=np.float64)
        header.attrs["Flag_Entropy_ICs"] = np.zeros(7, dtype=np.int32)
        header.attrs["NumFilesPerSnapshot"] = np.int32(1)
        header.attrs["Dimension"] = np.int32(3)
        header.attrs["Time"] = np.float64(0.0)
        units = f.create_group("Units")
        for name in ("Unit length in cgs (U_L)", "Unit mass in cgs (U_M)", "Unit time in cgs (U_t)",
                     "Unit current in cgs (U_I)", "Unit temperature in cgs (U_T)"):
            units.attrs[name] = np.float64(1.0)
        gas = f.create_group("PartType0")
        gas.create_dataset("Coordinates", data=positions.astype(np.float64))
        gas.create_dataset("Velocities", data=np.zeros((total, 3), dtype=np.float32))
        gas.create_dataset("Masses", data=np.full(total, mass, dtype=np.float32))
        gas.create_dataset("SmoothingLength", data=np.full(total, h_swift, dtype=np.float32))
        gas.create_dataset("InternalEnergy", data=u.astype(np.float32))
        gas.create_dataset("ParticleIDs", data=(index + 1).astype(np.uint64))
    print(f"make_sedov_ics: {n}^3 = {total} particles, mass {mass:.9g}, our h {h:.9g} (support {2 * h:.9g}), "
          f"SWIFT h {h_swift:.9g}, resolution_eta {2 * args.eta / KERNEL_GAMMA:.6g}, "
          f"u max {u.max():.6g} (background {u_background:.3g}), deposit weight sum {weight_sum:.9g}, "
          f"courant_dt {courant_dt:.6e}")


if __name__ == "__main__":
    main()
