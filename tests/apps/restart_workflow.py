# The restart workflow of a cluster user (issue 13, items 5-9), on sod 1D: a run made in chunks
# (max_steps, a stop file, a wall-time limit, each resumed with the command the run prints, on 2
# and 1 ranks) is one output series and one statistics file, bitwise the uninterrupted run's; a
# run with checkpoint_every=3 is bitwise the run without; bad checkpoints and changed parameters
# are refused with messages naming file, attribute, dataset or key.
# Usage: restart_workflow.py SOD PARAMETER_FILE MPIEXEC NUMPROC_FLAG [MPIEXEC_FLAGS...]
import os
import shlex
import shutil
import subprocess
import sys

import h5py
import numpy

sod, parameter_file, mpiexec, numproc = sys.argv[1:5]
mpi_flags = sys.argv[5:]
common = [parameter_file, "--set", "particles=200", "--set", "output_every=0.02", "--set", "progress_every=0",
          "--set", "diagnostics_every=0", "--no-timers"]
failures = []


def check(condition, what):
    if not condition:
        failures.append(what)
        print("FAILED:", what)


def run(ranks, arguments, status=0, program=None):
    command = [mpiexec, numproc, str(ranks)] + mpi_flags + [program or sod] + arguments
    result = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True)
    check(result.returncode == status, "exit status %d (expected %d) of %s\n%s" %
          (result.returncode, status, " ".join(command), result.stdout[-3000:]))
    return result.stdout


def files(name):
    return ["--set", "output_file=%s.h5part" % name, "--set", "checkpoint_file=%s.checkpoint.h5part" % name]


def remove(*paths):
    for path in paths:
        if os.path.lexists(path):
            os.remove(path)


def series(path):
    """Every step: its attributes time, step, dt and its datasets, as bytes."""
    with h5py.File(path, "r") as f:
        steps = sorted((k for k in f if k.startswith("Step#")), key=lambda k: int(k[5:]))
        return [({a: f[k].attrs[a] for a in ("time", "step", "dt")},
                 {d: f[k][d][()].tobytes() for d in f[k]}) for k in steps]


def same_series(a, b, what):
    sa, sb = series(a), series(b)
    check([s[0]["step"] for s in sa] == [s[0]["step"] for s in sb],
          "%s: steps %s and %s" % (what, [s[0]["step"] for s in sa], [s[0]["step"] for s in sb]))
    check(sa == sb, "%s: %s and %s differ in some bit" % (what, a, b))


def resume_command(output):
    """The command the stopped run printed, as arguments (after the program)."""
    lines = output.splitlines()
    for k, line in enumerate(lines):
        if line.endswith("resume with"):
            return shlex.split(lines[k + 1])[1:]
    check(False, "no resume command in\n" + output[-2000:])
    return []


for name in ("full", "every3", "chunked", "refused"):
    remove(name + ".h5part", name + ".checkpoint.h5part", name + ".statistics.txt", name + ".stop")

# The uninterrupted run, and the same with a checkpoint every 3 steps: bitwise the same series (9).
run(2, common + files("full"))
run(2, common + files("every3") + ["--set", "checkpoint_every=3"])
same_series("full.h5part", "every3.h5part", "checkpoint_every=3 against none")
check(len(series("full.h5part")) >= 5, "the output series has at least 5 steps")

# A run in four chunks, each resumed with the printed command (5, 6, 7): max_steps on 2 ranks,
# then on 1 rank a stop file present at the start, then a wall-time limit, then to the end.
out = run(2, common + files("chunked") + ["--set", "max_steps=40"])
check("max_steps = 40 reached" in out, "the max_steps stop is reported")
check(os.path.exists("chunked.checkpoint.h5part"), "max_steps wrote a checkpoint")
check(not os.path.exists("chunked.h5part.partial"), "the stopped run committed its output")
resume = resume_command(out)
check("restart_file=chunked.checkpoint.h5part" in resume and "max_steps=0" in resume,
      "the resume command names the checkpoint and lifts max_steps: %s" % resume)
open("chunked.stop", "w").close()
out = run(1, resume)
check("stop file 'chunked.stop' found (removed)" in out, "the stop file stops the run\n" + out[-2000:])
check(not os.path.exists("chunked.stop"), "the stop file is removed")
check("continuing the output series of 'chunked.h5part'" in out, "the restart continues the series")
out = run(1, resume_command(out) + ["--set", "wall_time_limit=1e-9"])
check("wall_time_limit = 1e-09 s reached" in out, "the wall-time limit stops the run\n" + out[-2000:])
out = run(1, resume_command(out) + ["--set", "wall_time_limit=0"])
check("stopped at step" not in out, "the last chunk runs to end_time")
same_series("full.h5part", "chunked.h5part", "the chunked run against the uninterrupted one")
full_rows = numpy.loadtxt("full.statistics.txt")
chunk_rows = numpy.loadtxt("chunked.statistics.txt")
check(full_rows.shape == chunk_rows.shape and (full_rows == chunk_rows).all(),
      "the chunked statistics file has the uninterrupted run's rows")

# A restart that fails leaves the series it would continue intact (the copy is in .partial).
before = open("chunked.h5part", "rb").read()
shutil.copy("every3.checkpoint.h5part", "bad.h5part")
run(1, common + files("chunked") + ["--set", "restart_file=bad.h5part", "--set", "gamma=1.6"], status=2)
check(open("chunked.h5part", "rb").read() == before, "a refused restart leaves the output unchanged")


# Checkpoints a restart refuses (8): exit status 3, the file and attribute or dataset named.
def bad_checkpoint(change, message, arguments=()):
    shutil.copy("chunked.checkpoint.h5part", "bad.h5part")
    with h5py.File("bad.h5part", "r+") as f:
        change(f["Step#0"])
    out = run(1, common + files("refused") + ["--set", "restart_file=bad.h5part"] + list(arguments), status=3)
    check(message in out, "message '%s' in\n%s" % (message, out[-2000:]))


def replace_dataset(step, name, values):
    del step[name]
    step[name] = values


bad_checkpoint(lambda s: s.attrs.__setitem__("dt", -1.0),
               "checkpoint 'bad.h5part' Step#0: attribute 'dt' = -1 must be finite and > 0")
bad_checkpoint(lambda s: s.attrs.__delitem__("dt"), "checkpoint 'bad.h5part' Step#0: no attribute 'dt'")
bad_checkpoint(lambda s: s.attrs.__delitem__("step"), "checkpoint 'bad.h5part' Step#0: no attribute 'step'")
bad_checkpoint(lambda s: [s.attrs.__setitem__(a, float("nan")) for a in ("time", "TimeValue")],
               "checkpoint 'bad.h5part' Step#0: attribute 'time' = nan is not finite")
bad_checkpoint(lambda s: None, "is not before end_time = 0.001", ["--set", "end_time=0.001"])
bad_checkpoint(lambda s: replace_dataset(s, "id", s["id"][()].astype(numpy.float64)),
               "checkpoint 'bad.h5part' Step#0 dataset 'id' holds double values: ids must be integers")
bad_checkpoint(lambda s: replace_dataset(s, "id", numpy.where(s["id"][()] == 5, 9, s["id"][()])),
               "checkpoint 'bad.h5part' Step#0 dataset 'id': id 9 belongs to more than one particle")

# Parameters that change the solution (8): exit status 2 naming each key with both values, unless
# allowed; free keys (files, cadences, limits) change freely.
shutil.copy("chunked.checkpoint.h5part", "bad.h5part")
out = run(1, common + files("refused") + ["--set", "restart_file=bad.h5part", "--set", "gamma=1.6",
                                           "--set", "kernel=wendland_c2"], status=2)
check("gamma: checkpoint 1.4, this run 1.6" in out and "kernel: checkpoint" in out,
      "both changed keys named with both values\n" + out[-2000:])
check("output_file" not in out.split("would change the solution")[-1], "free keys are not listed")
allowed = common + files("refused") + ["--set", "restart_file=bad.h5part", "--set", "gamma=1.6", "--set",
                                        "allow_parameter_changes=gamma", "--set", "max_steps=50"]
run(1, allowed)
# Once more from the same checkpoint: the statistics file then holds only the first restart's mark.
run(1, allowed)
steps = [s[0]["step"] for s in series("refused.h5part")]
check(steps == [42, 50], "a restart without an earlier output starts a series at its step; the second "
      "restart replaced the first one's steps: %s" % steps)

remove("bad.h5part")
if failures:
    print("%d checks failed" % len(failures))
    sys.exit(1)
print("restart workflow: every check passed")
