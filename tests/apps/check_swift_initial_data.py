"""Initial data from SWIFT-format initial conditions (initial_data = a file in the layout of SWIFT's
makeIC.py scripts, e.g. examples/HydroTests/SedovBlast_2D/makeIC.py): Header (BoxSize, NumPart_Total,
NumPart_Total_HighWord, NumPart_ThisFile, Time, NumFilesPerSnapshot, MassTable, Flag_Entropy_ICs,
Dimension), Units, PartType0 (Coordinates N x 3, Velocities N x 3 in float32 as makeIC writes them,
Masses, SmoothingLength, InternalEnergy, ParticleIDs as uint64, Density), written here with h5py
from the t = 0 step of a Sedov 2D run.

    check_swift_initial_data.py SEDOV PARAMETERS MPIEXEC [MPIEXEC FLAGS...]

1. the built-in Sedov 2D (32^2, 20 steps) on 2 ranks, output at every step;
2. the same from the SWIFT-format file on 2 ranks (read in parallel), from the built-in run's own
   t = 0 snapshot (SWIFT's plural snapshot names) on 2 ranks and from the same particles as H5Part
   initial data (its Step#0) on 1 rank: the outputs equal bit for bit at every step, and the last
   step equal to the built-in run's;
3. bad files (no SmoothingLength, another Dimension, entropies, other units, gas counted wrong in
   NumPart_Total or NumPart_ThisFile, a non-zero MassTable[0], a PartType1 group without a count,
   positions in SWIFT's [0, BoxSize) box against the run's [-0.5, 0.5), a step of an H5Part file asked for): exit status 2 or 3 with a message naming the file and what is
   wrong.
"""
import os
import subprocess
import sys

import h5py
import numpy as np

PROGRAM = "check_swift_initial_data"
FIELDS = ("x", "y", "z", "vx", "vy", "vz", "m", "rho", "P", "u", "h", "id", "kind", "cs", "du_dt")


def run(command, expect=0):
    result = subprocess.run(command, capture_output=True, text=True)
    output = result.stdout + result.stderr
    if (expect == 0) != (result.returncode == 0) or (expect and result.returncode != expect):
        print(output)
        sys.exit(f"{PROGRAM}: exit status {result.returncode} (expected {expect}) from {' '.join(command)}")
    return output


def write_swift_ic(path, step, dimension=2, drop=None, header=None, units=1.0, shift=0.0, extra_group=None):
    """Step `step` (an h5py group) as SWIFT's makeIC.py writes initial conditions (positions moved
    by `shift`: 0.5 puts them in SWIFT's [0, BoxSize) box; `extra_group`: another empty group)."""
    n = len(step["x"])
    coordinates = np.column_stack([step["x"][()] + shift, step["y"][()] + shift, step["z"][()]])
    velocities = np.column_stack([step["vx"][()], step["vy"][()], step["vz"][()]])
    with h5py.File(path, "w") as f:
        g = f.create_group("Header")
        g.attrs["BoxSize"] = 1.0
        g.attrs["NumPart_Total"] = [n, 0, 0, 0, 0, 0]
        g.attrs["NumPart_Total_HighWord"] = [0, 0, 0, 0, 0, 0]
        g.attrs["NumPart_ThisFile"] = [n, 0, 0, 0, 0, 0]
        g.attrs["Time"] = 0.0
        g.attrs["NumFilesPerSnapshot"] = 1
        g.attrs["MassTable"] = [0.0] * 6
        g.attrs["Flag_Entropy_ICs"] = 0
        g.attrs["Dimension"] = dimension
        for name, value in (header or {}).items():
            g.attrs[name] = value
        u = f.create_group("Units")
        for name in ("Unit length in cgs (U_L)", "Unit mass in cgs (U_M)", "Unit time in cgs (U_t)",
                     "Unit current in cgs (U_I)", "Unit temperature in cgs (U_T)"):
            u.attrs[name] = units if name.startswith("Unit length") else 1.0
        if extra_group:
            f.create_group(extra_group)
        p = f.create_group("PartType0")
        datasets = {"Coordinates": (coordinates, "d"), "Velocities": (velocities, "f"), "Masses": (step["m"][()], "d"),
                    "SmoothingLength": (step["h"][()], "d"), "InternalEnergy": (step["u"][()], "d"),
                    "ParticleIDs": (step["id"][()], "L"), "Density": (step["rho"][()], "d")}
        for name, (values, kind) in datasets.items():
            if name != drop:
                p.create_dataset(name, data=values, dtype=kind)


def write_h5part_initial_data(path, step):
    with h5py.File(path, "w") as f:
        g = f.create_group("Step#0")
        for name in ("x", "y", "z", "vx", "vy", "vz", "m", "h", "u", "id", "rho"):
            g.create_dataset(name, data=step[name][()])


def compare_outputs(a, b, steps=None):
    """Every step (or the last), every dataset of `a` and `b` byte for byte; the differences."""
    differences = []
    with h5py.File(a, "r") as x, h5py.File(b, "r") as y:
        ka = sorted((k for k in x if k.startswith("Step#")), key=lambda k: int(k[5:]))
        kb = sorted((k for k in y if k.startswith("Step#")), key=lambda k: int(k[5:]))
        if steps == "last":
            ka, kb = ka[-1:], kb[-1:]
        if len(ka) != len(kb):
            return [f"{a} has {len(ka)} steps, {b} {len(kb)}"]
        for sa, sb in zip(ka, kb):
            if x[sa].attrs["TimeValue"] != y[sb].attrs["TimeValue"]:
                differences.append(f"{sa}: time {x[sa].attrs['TimeValue']} != {y[sb].attrs['TimeValue']}")
            for name in FIELDS:
                u, v = x[sa][name][()], y[sb][name][()]
                if u.dtype != v.dtype or u.tobytes() != v.tobytes():
                    differences.append(f"{sa}/{name} of {a} and {sb}/{name} of {b} differ")
    return differences


def main():
    sedov, parameters, mpiexec, *flags = sys.argv[1:]
    common = [parameters, "--set", "particles_per_side=32", "--set", "max_steps=20", "--set", "output_every=1e-9",
              "--set", "progress_every=0", "--set", "diagnostics_every=0", "--no-timers"]
    def on(ranks):
        return [mpiexec, *flags, "-n", str(ranks), sedov]

    # With snapshots too: builtin_0000.hdf5, the t = 0 snapshot, read back as initial data below.
    run(on(2) + common + ["--set", "output_file=builtin.h5part", "--set", "output_format=both"])
    with h5py.File("builtin.h5part", "r") as f:
        first = f["Step#0"]
        write_swift_ic("sedov_ic.hdf5", first)
        write_h5part_initial_data("sedov_ic.h5part", first)
        write_swift_ic("bad_no_h.hdf5", first, drop="SmoothingLength")
        write_swift_ic("bad_dimension.hdf5", first, dimension=3)
        write_swift_ic("bad_entropy.hdf5", first, header={"Flag_Entropy_ICs": [1, 0, 0, 0, 0, 0]})
        write_swift_ic("bad_units.hdf5", first, units=3.0857e21)
        write_swift_ic("bad_count.hdf5", first, header={"NumPart_Total": [len(first["x"]) + 1, 0, 0, 0, 0, 0]})
        write_swift_ic("bad_types.hdf5", first, header={"NumPart_Total": [len(first["x"]), 5, 0, 0, 0, 0]})
        # Header fields that disagree with the data, and SWIFT's [0, BoxSize) box (issue 38, item 9)
        write_swift_ic("bad_this_file.hdf5", first, header={"NumPart_ThisFile": [len(first["x"]) - 1, 0, 0, 0, 0, 0]})
        write_swift_ic("bad_mass_table.hdf5", first, header={"MassTable": [1e-3, 0, 0, 0, 0, 0]})
        write_swift_ic("bad_part_type1.hdf5", first, extra_group="PartType1")
        write_swift_ic("bad_box.hdf5", first, shift=0.5)
    log = run(on(2) + common + ["--set", "initial_data=sedov_ic.hdf5", "--set", "output_file=from_swift.h5part"])
    if "1024 initial particles from 'sedov_ic.hdf5' (SWIFT-format initial conditions)" not in log:
        print(log)
        sys.exit(f"{PROGRAM}: the run did not report reading the SWIFT-format file")
    run(on(1) + common + ["--set", "initial_data=sedov_ic.h5part", "--set", "output_file=from_h5part.h5part"])
    failures = compare_outputs("from_swift.h5part", "from_h5part.h5part")
    failures += compare_outputs("from_swift.h5part", "builtin.h5part", steps="last")
    # The project's own snapshot (plural dataset names, as SWIFT's snapshots) as initial data.
    log = run(on(2) + common + ["--set", "initial_data=builtin_0000.hdf5", "--set", "output_file=from_snapshot.h5part"])
    if "1024 initial particles from 'builtin_0000.hdf5'" not in log:
        failures.append(f"the snapshot builtin_0000.hdf5 was not read as initial data:\n{log}")
    else:
        failures += compare_outputs("from_snapshot.h5part", "from_h5part.h5part")
    bad = [("bad_no_h.hdf5", 3, "'bad_no_h.hdf5' has no dataset PartType0/SmoothingLength (read as h)"),
           ("bad_dimension.hdf5", 3, "'bad_dimension.hdf5' Header/Dimension = 3, but this run is 2D"),
           ("bad_entropy.hdf5", 3, "'bad_entropy.hdf5' has Header/Flag_Entropy_ICs = 1"),
           ("bad_units.hdf5", 3, "'bad_units.hdf5' has Units/Unit length in cgs (U_L) = 3.0857e+21 but the run's "
                                 "unit_length_in_cgs = 1"),
           ("bad_count.hdf5", 3, "'bad_count.hdf5' Header/NumPart_Total[0] = 1025 but PartType0 holds 1024"),
           ("bad_types.hdf5", 3, "'bad_types.hdf5' holds 5 particles of type 1"),
           ("bad_this_file.hdf5", 3, "'bad_this_file.hdf5' has Header/NumPart_ThisFile[0] = 1023 but PartType0 "
                                     "holds 1024 particles"),
           ("bad_mass_table.hdf5", 3, "'bad_mass_table.hdf5' has Header/MassTable[0] = 0.001"),
           ("bad_part_type1.hdf5", 3, "'bad_part_type1.hdf5' has a group PartType1 but Header/NumPart_Total[1] = 0"),
           ("bad_box.hdf5", 3, "'bad_box.hdf5' PartType0/Coordinates lie outside this run's periodic box; "
                               "axis 0: [-0.5, 0.5)")]
    for path, status, message in bad:
        output = run(on(2) + common + ["--set", f"initial_data={path}", "--set", "output_file=bad.h5part"], expect=status)
        if message not in output:
            failures.append(f"{path}: the message lacks \"{message}\":\n{output}")
    output = run(on(1) + common + ["--set", "initial_data=sedov_ic.hdf5", "--set", "initial_data_step=0",
                                   "--set", "output_file=bad.h5part"], expect=2)
    if "initial_data_step = 0 chooses a step of an H5Part file" not in output:
        failures.append(f"initial_data_step with a SWIFT file: the message lacks the key:\n{output}")
    for failure in failures:
        print(f"{PROGRAM}: FAILED: {failure}")
    if failures:
        sys.exit(1)
    print(f"{PROGRAM}: Sedov 2D from SWIFT-format initial conditions (2 ranks) equals the run from the same "
          f"particles as H5Part (1 rank) at every step and the built-in run at its last; {len(bad) + 1} bad files refused")


if __name__ == "__main__":
    main()
