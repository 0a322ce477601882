#!/usr/bin/python3
# Nothing a user names is destroyed (issue 38, items 1 and 6): every file a run reads or writes
# (the parameter file, output, checkpoint, restart, initial data, statistics, used parameters,
# stop file, --trace) is one file each, also through links, else exit status 2 naming both keys
# and nothing touched; a stop file, a --trace file or an --output of h5part_to_ascii is never
# something else than a regular file of its own; a failed run (parameter error, failed check)
# leaves the earlier .used.par and .statistics.txt as they were, a successful one replaces them;
# the documented rerun `sod sod.used.par` still works.
#
#   run_files.py SOD H5PART_TO_ASCII PARAMETER_FILE MPIEXEC NUMPROC_FLAG [MPIEXEC_FLAGS...]
import os
import shutil
import subprocess
import sys

sod, to_ascii, parameter_file, mpiexec, numproc = sys.argv[1:6]
mpiexec_flags = sys.argv[6:]
failures = []
top = os.getcwd()
SMALL = ["--set", "particles=100", "--set", "max_steps=2", "--no-timers"]


def check(condition, what):
    print(("ok    " if condition else "FAIL  ") + what)
    if not condition:
        failures.append(what)


def run(arguments, program=None, timeout=60):
    command = [mpiexec, numproc, "1"] + mpiexec_flags + [program or sod] + arguments
    try:
        done = subprocess.run(command, stdout=subprocess.PIPE, stderr=subprocess.STDOUT, text=True, timeout=timeout)
    except subprocess.TimeoutExpired:
        return "timeout", ""
    return done.returncode, done.stdout


def content(path):
    with open(path, "rb") as f:
        return f.read()


def fresh(folder):
    shutil.rmtree(folder, ignore_errors=True)
    os.makedirs(folder)
    shutil.copy(parameter_file, os.path.join(folder, "in.par"))
    return folder


def refused(name, arguments, message, keep=("in.par",), program=None, status=2, folders=()):
    """A case that must exit with `status`, print `message` and leave the files `keep` unchanged."""
    folder = fresh("run_files_" + name)
    for path in folders:
        os.makedirs(os.path.join(folder, path))
    before = {path: content(os.path.join(folder, path)) for path in keep if os.path.isfile(os.path.join(folder, path))}
    cwd = os.getcwd()
    os.chdir(folder)
    try:
        code, output = run(arguments, program)
    finally:
        os.chdir(cwd)
    check(code == status, f"{name}: exit status {code}, expected {status}")
    check(message in output, f"{name}: the message names it ('{message}')")
    if message not in output or code != status:
        print(output[-2000:])
    for path, data in before.items():
        full = os.path.join(folder, path)
        check(os.path.isfile(full) and content(full) == data, f"{name}: {path} unchanged")


# The parameter file is one of the run's files: no key (and no --trace) may name it.
for key in ("stop_file", "output_file", "checkpoint_file", "statistics_file", "used_parameters_file"):
    refused("parameter_file_as_" + key, ["in.par"] + SMALL + ["--set", key + "=in.par"],
            key + " 'in.par' is also the parameter file 'in.par'")
refused("parameter_file_as_trace", ["in.par"] + SMALL + ["--trace", "in.par"],
        "--trace 'in.par' is also the parameter file 'in.par'")
# ... also through a hard link or a symbolic link to it.
folder = fresh("run_files_hard_link")
os.link(os.path.join(folder, "in.par"), os.path.join(folder, "linked.par"))
os.chdir(folder)
code, output = run(["in.par"] + SMALL + ["--set", "output_file=linked.par"])
os.chdir(top)
check(code == 2 and "output_file 'linked.par' is also the parameter file 'in.par'" in output,
      f"hard link: output_file on a hard link of the parameter file refused (exit {code})")
check(content(os.path.join(folder, "in.par")) == content(parameter_file), "hard link: the parameter file unchanged")
# The trace is checked against every other file: it would replace the output.
refused("trace_is_output", ["in.par"] + SMALL + ["--set", "output_file=out.h5part", "--trace", "out.h5part"],
        "--trace 'out.h5part' is also output_file 'out.h5part'")
# A fifo as --trace is refused at start-up (it used to wait for a reader for ever).
folder = fresh("run_files_trace_fifo")
os.mkfifo(os.path.join(folder, "trace.json"))
os.chdir(folder)
code, output = run(["in.par"] + SMALL + ["--trace", "trace.json"], timeout=30)
os.chdir(top)
check(code == 2 and "cannot write the --trace file 'trace.json'" in output,
      f"trace fifo: refused at start-up (exit {code}), no hang")
# A fifo as restart_file or initial_data is refused (exit 3), not opened: opening it waited for a
# writer for ever (the fuzz campaign of seed 7 found it).
for key in ("restart_file", "initial_data"):
    folder = fresh("run_files_read_fifo_" + key)
    os.mkfifo(os.path.join(folder, "input.h5part"))
    os.chdir(folder)
    code, output = run(["in.par"] + SMALL + ["--set", key + "=input.h5part"], timeout=30)
    os.chdir(top)
    check(code == 3 and "cannot open 'input.h5part': it is not a regular file" in output,
          f"{key} fifo: refused (exit {code}), no hang")
# A stop file that is not a regular file is refused, and stays what it was.
folder = fresh("run_files_stop_folder")
os.mkdir(os.path.join(folder, "stop_here"))
os.chdir(folder)
code, output = run(["in.par"] + SMALL + ["--set", "stop_file=stop_here"])
os.chdir(top)
check(code == 2 and "stop_file = 'stop_here' is a directory, not a regular file" in output,
      f"stop folder: refused (exit {code})")
check(os.path.isdir(os.path.join(folder, "stop_here")), "stop folder: still there")
# (Never a real device here: the code before the fix removed whatever the stop file named, and
# tests may run as root.) A symbolic link to the parameter file, and a fifo:
folder = fresh("run_files_stop_link")
os.symlink("in.par", os.path.join(folder, "link.stop"))
os.chdir(folder)
code, output = run(["in.par"] + SMALL + ["--set", "stop_file=link.stop"])
os.chdir(top)
check(code == 2 and "stop_file 'link.stop' is also the parameter file 'in.par'" in output,
      f"stop link: refused (exit {code})")
check(os.path.islink(os.path.join(folder, "link.stop")) and
      content(os.path.join(folder, "in.par")) == content(parameter_file), "stop link: the link and its target unchanged")
folder = fresh("run_files_stop_fifo")
os.mkfifo(os.path.join(folder, "fifo.stop"))
os.chdir(folder)
code, output = run(["in.par"] + SMALL + ["--set", "stop_file=fifo.stop"])
os.chdir(top)
check(code == 2 and "stop_file = 'fifo.stop' is a fifo, not a regular file" in output, f"stop fifo: refused (exit {code})")
check(os.path.exists(os.path.join(folder, "fifo.stop")), "stop fifo: still there")
# A regular stop file is still the user's way to stop a run: found, removed, the run stops.
folder = fresh("run_files_stop_regular")
open(os.path.join(folder, "please.stop"), "w").close()
os.chdir(folder)
code, output = run(["in.par"] + SMALL + ["--set", "stop_file=please.stop", "--set", "checkpoint_file=c.h5part"])
os.chdir(top)
check(code == 0 and "stop file 'please.stop' found (removed)" in output and
      not os.path.exists(os.path.join(folder, "please.stop")), f"stop file: a regular one stops the run (exit {code})")

# h5part_to_ascii never writes over its input.
folder = fresh("run_files_to_ascii")
os.chdir(folder)
code, output = run(["in.par"] + SMALL + ["--set", "output_file=run.h5part"])
before = content("run.h5part")
code, output = run(["run.h5part", "--output", "./run.h5part"], program=to_ascii)
os.chdir(top)
check(code == 2 and "--output './run.h5part' is the input file 'run.h5part'" in output,
      f"h5part_to_ascii: --output = its input refused (exit {code})")
check(content(os.path.join(folder, "run.h5part")) == before, "h5part_to_ascii: the input unchanged")

# Item 2: a name too long for Open MPI's MPI-IO (which aborts with "buffer overflow detected" on
# 240 characters) is refused at start-up naming the key; a long absolute path whose relative form
# is short is opened by the short one and works.
refused("long_output_name", ["in.par"] + SMALL + ["--set", "output_file=" + "o" * 233 + ".h5part"],
        "output_file: '" + "o" * 233 + ".h5part.partial' has a file name of 248 characters")
refused("long_checkpoint_path", ["in.par"] + SMALL + ["--set", "checkpoint_file=" + ("d" * 120 + "/") * 2 + "c.h5part"],
        "checkpoint_file: '" + ("d" * 120 + "/") * 2 + "c.h5part.partial' is 258 characters long",
        folders=[("d" * 120 + "/") * 2])
folder = fresh("run_files_long_absolute")
deep = os.path.join(os.path.abspath(folder), "d" * 200, "e" * 50)
os.makedirs(deep)
shutil.copy(parameter_file, os.path.join(deep, "in.par"))
os.chdir(deep)
code, output = run(["in.par"] + SMALL + ["--set", "output_file=" + os.path.join(deep, "x.h5part"),
                                         "--set", "checkpoint_file=" + os.path.join(deep, "c.h5part")])
os.chdir(top)
check(code == 0 and os.path.isfile(os.path.join(deep, "x.h5part")) and os.path.isfile(os.path.join(deep, "c.h5part")),
      f"long absolute path ({len(os.path.join(deep, 'x.h5part'))} characters) in the working folder: written (exit {code})")

# Item 6: a failed run leaves the earlier .used.par and .statistics.txt; a successful one replaces them.
earlier = b"written by an earlier run\n"
for name, arguments, status in [
        ("parameter_error", ["--set", "rho_left=1e6"], 2),
        ("failed_check", ["--check-l1", "1e-9,1e-9,1e-9"], 1),
        ("runtime_error", ["--set", "gamma=1.0000000001"], 3)]:
    folder = fresh("run_files_keep_" + name)
    for suffix in (".used.par", ".statistics.txt"):
        with open(os.path.join(folder, "run" + suffix), "wb") as f:
            f.write(earlier)
    os.chdir(folder)
    code, output = run(["in.par"] + SMALL + ["--set", "output_file=run.h5part"] + arguments)
    os.chdir(top)
    check(code == status, f"failed run ({name}): exit status {code}, expected {status}")
    for suffix in (".used.par", ".statistics.txt"):
        check(content(os.path.join(folder, "run" + suffix)) == earlier, f"failed run ({name}): run{suffix} unchanged")
folder = fresh("run_files_replace")
for suffix in (".used.par", ".statistics.txt"):
    with open(os.path.join(folder, "run" + suffix), "wb") as f:
        f.write(earlier)
os.chdir(folder)
code, output = run(["in.par"] + SMALL + ["--set", "output_file=run.h5part"])
check(code == 0, f"successful run: exit status {code}")
for suffix in (".used.par", ".statistics.txt"):
    check(content("run" + suffix) != earlier and not os.path.exists("run" + suffix + ".partial"),
          f"successful run: run{suffix} replaced, no .partial left")
# The documented rerun: the used-parameters file as the parameter file, which it is again.
used = content("run.used.par")
code, output = run(["run.used.par", "--no-timers"])
check(code == 0, f"rerun `sod run.used.par`: exit status {code}")
check(content("run.used.par") == used, "rerun: run.used.par left as it was")
# ... but an override would change it: refused, naming both.
code, output = run(["run.used.par", "--set", "particles=120", "--no-timers"])
check(code == 2 and "used_parameters_file 'run.used.par' is also the parameter file" in output,
      f"rerun with an override: refused (exit {code})")
check(content("run.used.par") == used, "rerun with an override: run.used.par unchanged")
os.chdir(top)

print(f"{len(failures)} failures")
sys.exit(1 if failures else 0)
