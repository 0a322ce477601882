#!/usr/bin/python3
# Restarts never silently change the answer (issue 38, item 3): every value a restart reads is
# checked against the others. An individual-step checkpoint (sedov 2D) and a fluid one (dam
# break), each restarted as written (exit 0), then broken one way at a time with h5py: a step
# window ending at 2^62, a NaN time bin, swapped or zeroed step windows, the timeline's now moved
# back one tick, no 'time' attribute, a dt of 1e300. Each must exit with status 3 naming the
# file, the dataset or attribute and, for a particle's value, its id. The clock and run state
# carry checksums (root attribute 'checksums'): a changed value that no other check refuses (a
# global-step dt one ulp off, another step counter) is refused naming it, and so is a checkpoint
# without checksums; the dt of 1e300 is refused by the checksums, and, with checksums made to
# match it (as a faulty writer would), by the check against what was left of the run. The
# walls' accumulators are written with walls only, and a checkpoint of walls without them is
# refused.
#
#   restart_consistency.py SEDOV SEDOV_2D_PAR FLUID DAM_BREAK_PAR MPIEXEC NUMPROC_FLAG [MPIEXEC_FLAGS...]
import os
import shutil
import struct
import subprocess
import sys

import h5py
import numpy as np

sedov, sedov_par, fluid, dam_break_par, mpiexec, numproc = sys.argv[1:7]
mpiexec_flags = sys.argv[7:]
failures = []


def check(condition, what):
    print(("ok    " if condition else "FAIL  ") + what)
    if not condition:
        failures.append(what)


def run(program, arguments, ranks=1):
    command = [mpiexec, numproc, str(ranks)] + mpiexec_flags + [program] + arguments + ["--no-timers"]
    done = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=240)
    return done.returncode, done.stdout


def write_checkpoint(program, parameters, name, extra):
    code, output = run(program, [parameters, "--set", "output_file=none", "--set", "checkpoint_file=" + name] + extra)
    if code != 0:
        print(output)
        sys.exit(f"FAIL: writing the checkpoint {name} exited with {code}")


def broken(source, name, change):
    shutil.copy(source, name)
    with h5py.File(name, "r+") as f:
        change(f)
    return name


def fnv1a(kind, data):
    """64-bit FNV-1a of a value's kind byte and bytes (flecsi_lite/io/run_state_checksums.hh)."""
    h = 0xcbf29ce484222325
    for byte in bytes([kind]) + data:
        h = ((h ^ byte) * 0x100000001b3) % 2**64
    return h


def resealed_dt(value):
    """Sets Step#0's dt and its checksum line to match, as a faulty writer would have written it."""
    def change(f):
        f["Step#0"].attrs["dt"] = value
        lines = f.attrs["checksums"]
        lines = (lines.decode() if isinstance(lines, bytes) else lines).splitlines()
        lines = [("dt %016x" % fnv1a(1, struct.pack("<d", value))) if line.startswith("dt ") else line
                 for line in lines]
        f.attrs["checksums"] = "".join(line + "\n" for line in lines)
    return change


def replace_dataset(step, name, values):
    del step[name]
    step.create_dataset(name, data=values)


def refused(program, parameters, case, change, message, source, extra, ranks=1):
    path = broken(source, "restart_" + case + ".h5part", change)
    code, output = run(program, [parameters, "--set", "output_file=none", "--set", "restart_file=" + path] + extra,
                       ranks)
    check(code == 3, f"{case}: exit status {code}, expected 3")
    check(message in output, f"{case}: the message says '{message}'")
    if code != 3 or message not in output:
        print(output[-1500:])


# Individual time steps: sedov 2D, 256 particles, stopped by max_steps at step 6 (checkpointed).
individual = ["--set", "particles_per_side=16", "--set", "time_steps=individual"]
write_checkpoint(sedov, sedov_par, "individual.h5part", individual + ["--set", "max_steps=6"])
resume = individual + ["--set", "max_steps=8"]
code, output = run(sedov, [sedov_par, "--set", "output_file=none", "--set", "restart_file=individual.h5part"] + resume)
check(code == 0, f"individual: the checkpoint as written restarts (exit {code})")
with h5py.File("individual.h5part", "r") as f:
    step = f["Step#0"]
    ids, kinds = step["id"][()], step["kind"][()] if "kind" in step else None
    fluid_index = int(np.flatnonzero(kinds == 0)[0]) if kinds is not None else 0
    fluid_id = int(ids[fluid_index])
    now = int(f.attrs["state:timeline_now"])


def set_element(name, index, value):
    def change(f):
        values = f["Step#0"][name][()]
        values[index] = value
        f["Step#0"][name][...] = values
    return change


def as_nan_floats(f):
    values = f["Step#0"]["time_bin"][()].astype(np.float64)
    values[fluid_index] = np.nan
    replace_dataset(f["Step#0"], "time_bin", values)


def swapped(f):
    step = f["Step#0"]
    begin, end = step["step_begin"][()], step["step_end"][()]
    step["step_begin"][...], step["step_end"][...] = end, begin


def zeroed(f):
    for name in ("step_begin", "step_end"):
        f["Step#0"][name][...] = np.zeros_like(f["Step#0"][name][()])


def now_back(f):
    f.attrs["state:timeline_now"] = np.int64(now - 1)


cases = [
    ("step_end_2_62", set_element("step_end", fluid_index, 2**62),
     f"dataset 'step_end' = {2**62} is not after the timeline's now"),
    ("time_bin_nan", as_nan_floats, "dataset 'time_bin' holds double values: it must hold integers"),
    ("windows_swapped", swapped, "dataset 'step_begin' = "),
    ("windows_zeroed", zeroed, "dataset 'step_end' = 0 is not after the timeline's now"),
    ("timeline_now_minus_one", now_back, "attribute 'time' = "),
    ("no_time_attribute", lambda f: f["Step#0"].attrs.__delitem__("time"), "Step#0: no attribute 'time'"),
]
for case, change, message in cases:
    refused(sedov, sedov_par, case, change, message, "individual.h5part", resume)
# Values only the checksums tell from the written ones, and a checkpoint without them.
refused(sedov, sedov_par, "step_changed", lambda f: f["Step#0"].attrs.__setitem__("step", np.int64(3)),
        "Step#0 attribute 'step' differs from the value the writing run stored", "individual.h5part", resume)
refused(sedov, sedov_par, "initial_mass_changed",
        lambda f: f.attrs.__setitem__("state:initial_mass", 2 * f.attrs["state:initial_mass"]),
        "root attribute 'state:initial_mass' differs", "individual.h5part", resume)
refused(sedov, sedov_par, "no_checksums", lambda f: f.attrs.__delitem__("checksums"),
        "has no root attribute 'checksums'", "individual.h5part", resume)
# The particle is named by its id.
refused(sedov, sedov_par, "step_end_names_id", set_element("step_end", fluid_index, 2**62),
        f"for the particle with id {fluid_id}", "individual.h5part", resume, ranks=2)

# The fluid (global steps): a dt longer than what was left of the run that wrote it.
small_fluid = ["--set", "particles=10", "--set", "max_steps=3"]
write_checkpoint(fluid, dam_break_par, "fluid.h5part", small_fluid)
code, output = run(fluid, [dam_break_par, "--set", "output_file=none", "--set", "restart_file=fluid.h5part",
                           "--set", "particles=10", "--set", "max_steps=4"])
check(code == 0, f"fluid: the checkpoint as written restarts (exit {code})")
fluid_resume = ["--set", "particles=10", "--set", "max_steps=4"]
refused(fluid, dam_break_par, "fluid_dt_1e300", lambda f: f["Step#0"].attrs.__setitem__("dt", 1e300),
        "Step#0 attribute 'dt' differs from the value the writing run stored", "fluid.h5part", fluid_resume)
refused(fluid, dam_break_par, "fluid_dt_1e300_resealed", resealed_dt(1e300),
        "attribute 'dt' = 1.0000000000000001e+300 is longer than what was left of the run", "fluid.h5part",
        fluid_resume)
with h5py.File("fluid.h5part", "r") as f:
    fluid_dt = float(f["Step#0"].attrs["dt"])
refused(fluid, dam_break_par, "fluid_dt_next", lambda f: f["Step#0"].attrs.__setitem__("dt", np.nextafter(fluid_dt, 1)),
        "Step#0 attribute 'dt' differs", "fluid.h5part", fluid_resume, ranks=2)

# The walls' accumulators are in the checkpoints of runs with walls only (the "walls" feature):
# the dam break's has them, Sedov's (no walls) not; a checkpoint with walls but without them is
# refused, naming the dataset.
with h5py.File("fluid.h5part", "r") as f, h5py.File("individual.h5part", "r") as g:
    check("boundary_work" in f["Step#0"] and "impulse_x" in f["Step#0"], "fluid: the walls' accumulators are written")
    check("boundary_work" not in g["Step#0"] and "impulse_x" not in g["Step#0"],
          "individual (no walls): no walls' accumulators written")
refused(fluid, dam_break_par, "fluid_without_wall_work", lambda f: f["Step#0"].__delitem__("boundary_work"),
        "holds wall particles (kind = 1) but no dataset boundary_work", "fluid.h5part", fluid_resume)

print(f"{len(failures)} failures")
sys.exit(1 if failures else 0)
