#!/usr/bin/python3
# The run's own records (issue 13, items 11 and 12): the start-up banner (version, ranks, the
# particles really created), the statistics file read with numpy.loadtxt (one row per step, the
# energy column equal to the conserved lines, a restart appending to the file of the run it
# continues), and the used-parameters file as a rerun file that gives the same output bitwise.
#
#   statistics_file.py VERSION COMPARE_H5PART SOD PARAMETER_FILE MPIEXEC NUMPROC_FLAG [MPIEXEC_FLAGS...]
import os
import re
import subprocess
import sys

import h5py
import numpy as np

version, compare, sod, parameter_file, mpiexec, numproc = sys.argv[1:7]
mpiexec_flags = sys.argv[7:]
failures = []


def check(condition, what):
    print(("ok    " if condition else "FAIL  ") + what)
    if not condition:
        failures.append(what)


def run(ranks, *arguments, status=0):
    command = [mpiexec, numproc, str(ranks)] + mpiexec_flags + [sod] + list(arguments) + ["--no-timers"]
    done = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=240)
    if done.returncode != status:
        print(done.stdout)
        sys.exit(f"FAIL: {' '.join(command)} exited with {done.returncode}, not {status}")
    return done.stdout


def read_statistics(path):
    with open(path) as text:
        lines = text.read().splitlines()
    names = [line[2:].split() for line in lines if line.startswith("# step ")]
    check(len(names) == 1, f"{path}: one column line")
    return lines, names[0], np.loadtxt(path, ndmin=2)


common = ["--set", "particles=200", "--set", "progress_every=0", "--set", "diagnostics_every=1",
          "--set", "checkpoint_every=100"]
log = run(2, parameter_file, *common, "--set", "output_file=stats_run.h5part",
          "--set", "checkpoint_file=stats_run.checkpoint.h5part")

# The banner: version and commit, ranks and threads, then the particles as created.
banner = re.search(r"^sod (\S+) \(git (\S+)\): 2 MPI ranks x 1 threads per rank$", log, re.M)
check(banner is not None and banner.group(1) == version, f"banner names version {version} and 2 ranks")
particles = re.search(r"^sod: (\d+) particles \((\d+) fluid, (\d+) walls\), (\d+) to (\d+) per rank; "
                      r"kernel cubic_spline, eos ideal_gas \(gamma 1.4\)$", log, re.M)
check(particles is not None, "banner line of the particles, kernel and EOS")
total, fluid, walls, fewest, most = (int(g) for g in particles.groups())
with h5py.File("stats_run.h5part", "r") as output:
    written = len(output["Step#0"]["x"])
check(total == written and fluid + walls == total, f"banner count {total} is the written count {written}")
check(fewest + most == total and fewest <= most, f"per rank {fewest} to {most} adds up to {total} on 2 ranks")

# The statistics file: one row per step, the energy of every conserved line, the time steps.
lines, names, rows = read_statistics("stats_run.statistics.txt")
column = {name: rows[:, names.index(name)] for name in names}
check(names[:7] == ["step", "time", "dt", "kinetic", "internal", "walls", "total"] and
      names[-3:] == ["momentum_x", "mass", "mean_neighbours"], "columns of 1D: no angular momentum")
check(any("code units" in line for line in lines) and any(line.startswith("#   particles = 200") for line in lines),
      "header names the units and the parameters")
steps = int(re.search(r"^sph: (\d+) steps to t = 0.2 ", log, re.M).group(1))
check(np.array_equal(column["step"], np.arange(steps + 1)), f"one row per step, 0 to {steps}")
conserved = {int(m.group(1)): (float(m.group(2)), float(m.group(3)))
             for m in re.finditer(r"^conserved: step (\d+) .*?mass (\S+) .* total (\S+)", log, re.M)}
check(sorted(conserved) == list(range(steps + 1)), "a conserved line per step (diagnostics_every = 1)")
energy = np.array([conserved[s][1] for s in range(steps + 1)])
check(np.all(np.abs(column["total"] - energy) <= 1e-11 * np.abs(energy)), "energy column = conserved totals (12 digits)")
check(np.all(column["mass"] == column["mass"][0]) and abs(column["mass"][0] - conserved[0][0]) <= 1e-12,
      "mass column constant, the conserved mass")
parts = column["kinetic"] + column["internal"] + column["walls"]
check(np.all(np.abs(parts - column["total"]) <= 1e-14 * np.abs(column["total"])), "total = kinetic + internal + walls")
check(column["dt"][0] == 0 and np.allclose(np.diff(column["time"]), column["dt"][1:], rtol=1e-9, atol=0),
      "dt of each row is the step from the previous row")
check(column["time"][-1] == 0.2 and np.all(column["mean_neighbours"] > 0), "last row at end_time")

# A restart continues the run's file: its rows after the checkpoint are dropped, then rewritten.
restart_log = run(1, parameter_file, *common, "--set", "output_file=stats_restarted.h5part",
                  "--set", "checkpoint_file=stats_restarted.checkpoint.h5part",
                  "--set", "restart_file=stats_run.checkpoint.h5part",
                  "--set", "statistics_file=stats_run.statistics.txt")
restart_step = int(re.search(r"restarting at step (\d+)", restart_log).group(1))
check(0 < restart_step < steps, f"restart at step {restart_step}, before the end")
continued_lines, _, continued = read_statistics("stats_run.statistics.txt")
check(np.array_equal(continued, rows), "appended file = the uninterrupted run's rows, bit for bit, each step once")
kept = next(i for i, line in enumerate(lines) if not line.startswith("#") and int(line.split()[0]) == restart_step)
check(continued_lines[:kept + 1] == lines[:kept + 1] and continued_lines[kept + 1] == f"# restarted at step {restart_step}",
      "header and rows up to the restart kept as they were, then the restart marked")

# The used-parameters file reruns the run: the same output and statistics, bit for bit.
def assignments(path):
    with open(path) as text:
        return dict(line.split("#")[0].strip().split(" = ", 1) for line in text if not line.startswith("#"))


used = assignments("stats_run.used.par")
check(used["particles"] == "200" and used["eos"] == '"ideal_gas"' and used["viscosity_epsilon"] == "0.01",
      "used parameters hold every key, defaults included")
run(2, "stats_run.used.par", "--set", "output_file=stats_rerun.h5part",
    "--set", "checkpoint_file=stats_rerun.checkpoint.h5part")
same = subprocess.run([compare, "stats_run.h5part", "stats_rerun.h5part"], stdout=subprocess.PIPE, text=True)
check(same.returncode == 0, "rerun from the used parameters: the same output bitwise (" + same.stdout.strip() + ")")
check(np.array_equal(read_statistics("stats_rerun.statistics.txt")[2], rows), "rerun: the same statistics")
rerun = assignments("stats_rerun.used.par")
check({k for k in used if used[k] != rerun.get(k)} == {"output_file", "checkpoint_file"} and rerun.keys() == used.keys(),
      "rerun's used parameters differ only in the two overridden file names")

# statistics_every: rows at its multiples and at the last step; none: no file.
run(1, parameter_file, "--set", "particles=200", "--set", "output_file=stats_every.h5part",
    "--set", "statistics_every=7", "--set", "diagnostics_every=0", "--set", "progress_every=0")
every = read_statistics("stats_every.statistics.txt")[2][:, 0]
check(np.array_equal(every, np.append(np.arange(0, steps + 1, 7), steps)) or
      np.array_equal(every, np.arange(0, steps + 1, 7)), "statistics_every = 7: steps 0, 7, ... and the last")
run(1, parameter_file, "--set", "particles=200", "--set", "output_file=stats_none.h5part",
    "--set", "statistics_file=none", "--set", "used_parameters_file=none", "--set", "end_time=0.01")
check(not os.path.exists("stats_none.statistics.txt") and not os.path.exists("stats_none.used.par"),
      "statistics_file = none and used_parameters_file = none write nothing")

sys.exit(1 if failures else 0)
