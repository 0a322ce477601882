#!/usr/bin/env python3
# The class "silently different result" of issue 38 (item 10), judged on the run state of a
# checkpoint: every numeric attribute of Step#0 (time, TimeValue, dt, step) and of the root
# (state:*, the run state) is changed in turn (next double up, halved, doubled, negated, zeroed,
# NaN) and the run restarted from the changed copy for two more steps. The rule: a changed
# attribute is refused (exit 2 or 3) or the restart's last step equals the unchanged restart's
# bit for bit; an exit 0 with other bits is "silently different", any other exit status a "bad
# exit". Particle data are not changed here: the checkpoint's checksums cover its clock and run
# state only, so other positions are another valid input (their own checks are the fuzz test's).
#
#   /usr/bin/python3 tests/fuzz/restart_mutations.py build/apps/sod/sod apps/sod/sod_1d.par \
#       --work /tmp/restart_mutations --set particles=40
#
# CI runs it on a small sod checkpoint (fuzz.restart_mutations); docs/fuzzing.md has the counts.
import argparse
import os
import shutil
import subprocess
import sys
import tempfile

import h5py
import numpy as np

CHANGES = {"next": lambda v: np.nextafter(v, np.inf), "half": lambda v: v * 0.5, "double": lambda v: v * 2,
           "negative": lambda v: -v, "zero": lambda v: v * 0, "nan": lambda v: v * np.nan}


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("program")
    parser.add_argument("parameters")
    parser.add_argument("--work", required=True)
    parser.add_argument("--set", action="append", help="key=value for every run (e.g. particles=40)")
    options = parser.parse_args()
    program, parameters = os.path.abspath(options.program), os.path.abspath(options.parameters)
    shutil.rmtree(options.work, ignore_errors=True)
    os.makedirs(options.work)
    os.chdir(options.work)
    # An isolated singleton starts no orted daemon; isolated singletons share one session directory
    # under TMPDIR and remove it as they end, so this script's runs take one of their own.
    session = tempfile.TemporaryDirectory(prefix="flecsph-restart-mpi-")
    environment = dict(os.environ, OMP_NUM_THREADS="1", OMPI_MCA_ess_singleton_isolated="1", TMPDIR=session.name)
    common = ["--set", "progress_every=0", "--set", "diagnostics_every=0", "--no-timers"]
    for assignment in options.set or []:
        common += ["--set", assignment]

    def run(arguments):
        return subprocess.run([program, parameters] + common + arguments, env=environment, capture_output=True,
                              text=True)

    def restart(checkpoint):
        if os.path.exists("out.h5part"):
            os.remove("out.h5part")
        return run(["--set", "restart_file=" + checkpoint, "--set", "output_file=out.h5part", "--set", "max_steps=4"])

    def last_step():
        with h5py.File("out.h5part", "r") as f:
            name = max(f.keys(), key=lambda key: int(key.split("#")[1]))
            return {dataset: f[name][dataset][()].tobytes() for dataset in f[name]}

    made = run(["--set", "output_file=none", "--set", "checkpoint_every=1", "--set", "max_steps=2",
                "--set", "checkpoint_file=checkpoint.h5part"])
    if made.returncode != 0:
        sys.exit("restart_mutations: the checkpoint run failed:\n" + made.stderr)
    reference = restart("checkpoint.h5part")
    if reference.returncode != 0:
        sys.exit("restart_mutations: the unchanged restart failed:\n" + reference.stderr)
    expected = last_step()
    counts, silent = {"refused": 0, "same": 0, "silently different": 0, "bad exit": 0}, []
    for group in ("Step#0", "/"):
        with h5py.File("checkpoint.h5part", "r") as f:
            names = [n for n, v in f[group].attrs.items() if np.issubdtype(np.asarray(v).dtype, np.number)]
        for name in names:
            for label, change in CHANGES.items():
                shutil.copyfile("checkpoint.h5part", "changed.h5part")
                with h5py.File("changed.h5part", "r+") as f:
                    old = np.asarray(f[group].attrs[name])
                    if np.issubdtype(old.dtype, np.integer) and label in ("next", "nan"):
                        continue
                    new = np.asarray(change(old.astype(np.float64))).astype(old.dtype)
                    if np.array_equal(new, old, equal_nan=True):
                        continue
                    f[group].attrs[name] = new
                result = restart("changed.h5part")
                if result.returncode in (2, 3):
                    verdict = "refused"
                elif result.returncode != 0:
                    verdict = "bad exit"
                else:
                    verdict = "same" if last_step() == expected else "silently different"
                counts[verdict] += 1
                if verdict in ("silently different", "bad exit"):
                    silent.append("%s: %s %s %s (exit %d)" % (verdict.upper(), group, name, label, result.returncode))
    print("restart_mutations: %s" % ", ".join("%s: %d" % item for item in counts.items()))
    for case in silent:
        print(case)
    return 1 if silent else 0


if __name__ == "__main__":
    sys.exit(main())
