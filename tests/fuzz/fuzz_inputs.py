#!/usr/bin/env python3
# Bounded, seeded fuzz test of the apps' inputs (issues 13 and 38): mutations of the shipped
# parameter files of every app given (byte flips, truncations, duplicated or removed lines, huge
# numbers, garbage values, odd line ends); of small H5Part files (byte flips and truncations of an
# initial-data file and of checkpoints of a global-step, an individual-step, a self-gravity and a
# fluid run, read as initial_data and restart_file); and odd paths given to every file key and
# --trace (the parameter file itself, links to it, the earlier output, fifos, folders, names too
# long for MPI-IO, ...), each run on 1 rank. The classes of failure: a crash (a signal), a hang,
# a lost file (the earlier output, the parameter file or a file a link points to changed or
# removed), an exit status other than 0, 2 or 3, an unclear error (a non-zero exit without a
# message on stderr, or with a bare library message such as "stod") and HDF5 not closed (its
# "infinite loop closing library" at exit).
#
# Cheap cases: the parameter files are mutated after their particle counts are made small
# (SMALL_SIZES; a mutation can still set any count), a case runs at most one step, and the apps
# start as Open MPI singletons without a daemon (no mpiexec) unless --launcher says otherwise.
#
#   fuzz_inputs.py --sod build/apps/sod/sod --sedov build/apps/sedov/sedov --source . \
#                  [--evrard E --cold-collapse C --fluid F --bns B] --work fuzz_work [--seed 13]
#                  [--parameter-cases 200] [--h5part-cases 120] [--path-cases 60]
#                  [--launcher "mpiexec -n 1 --oversubscribe"] [--jobs 2]
#
# Deterministic: a case is a function of the seed and its number only, so a failure is replayed
# with --only N. Plain python3 (no h5py): the H5Part files are made by the apps themselves.
import argparse
import concurrent.futures
import os
import random
import re
import resource
import shlex
import shutil
import signal
import subprocess
import sys
import tempfile

ALLOWED_STATUSES = (0, 2, 3)
# Address space of one case: a valid but huge run (particles = 4294967296) fails its allocation
# at once with exit 3 instead of filling the memory of a shared machine.
ADDRESS_SPACE_LIMIT = 6 << 30

HUGE_NUMBERS = ["1e308", "-1e308", "1e309", "1e-320", "9223372036854775807", "9223372036854775808",
                "-9223372036854775808", "18446744073709551616", "4294967296", "2147483648",
                "99999999999999999999999", "1e300", "-0", "0"]
GARBAGE_VALUES = ["", "=", "= 1", "==", "nan", "-nan", "inf", "-inf", "1e", "0x10", "1,5", "1.2.3",
                  "true", "yes", "\x00", "\xff\xfe", "\u00fc", "#", "\"", "'", "--", "1 2", "-",
                  "none", "auto", "x" * 300, "1" * 400, "\t", "\\", "${HOME}", "../../..", "/"]
LINE_ENDS = ["\r", "\r\n", "\n\r", "\r\r\n"]
# The size key of each shipped parameter file and the value it gets before the mutations: one
# step of sedov_3d.par's 50^3 particles takes 17 s, of 8^3 a fraction of a second.
SMALL_SIZES = {"sod_1d.par": ("particles", 40), "sod_2d.par": ("particles", 12), "sod_3d.par": ("particles", 8),
               "sedov_2d.par": ("particles_per_side", 16), "sedov_3d.par": ("particles_per_side", 8),
               "evrard.par": ("particles", 300), "cold_collapse.par": ("particles", 300),
               "single_star.par": ("particles", 300), "dam_break.par": ("particles", 10),
               "dam_break_3d.par": ("particles", 4), "couette.par": ("particles", 8),
               "poiseuille.par": ("particles", 8), "still_tank.par": ("particles", 8)}
# Parameter files that need another file first (bns binaries: a relaxed star's star_file).
NEEDS_FILES = ("binary_stable.par", "merger.par", "inspiral.par")
APPS = ("sod", "sedov", "evrard", "cold_collapse", "fluid", "bns")


def parameter_files(options):
    files = []
    for app in APPS:
        if not getattr(options, app):
            continue
        folder = os.path.join(options.source, "apps", app)
        files += [(app, os.path.join(folder, name)) for name in sorted(os.listdir(folder))
                  if name.endswith(".par") and name not in NEEDS_FILES]
    return files


def small(name, data):
    """The parameter file's bytes with its particle count set to SMALL_SIZES' value."""
    if name not in SMALL_SIZES:
        return data
    key, value = SMALL_SIZES[name]
    pattern = re.compile(rb"^(%s[ \t]*=[ \t]*)[0-9]+" % key.encode(), re.MULTILINE)
    data, count = pattern.subn(rb"\g<1>%d" % value, data)
    if count != 1:
        sys.exit("fuzz_inputs: %s has no single '%s = N' line to make small" % (name, key))
    return data


def mutate_lines(rng, data):
    lines = data.split(b"\n")
    kind = rng.choice(["duplicate", "remove", "huge", "garbage", "long_key", "swap"])
    k = rng.randrange(len(lines))
    if kind == "duplicate":
        lines.insert(k, lines[k])
    elif kind == "remove":
        del lines[k]
    elif kind == "swap":
        j = rng.randrange(len(lines))
        lines[k], lines[j] = lines[j], lines[k]
    elif kind == "long_key":
        lines.insert(k, b"k" * rng.choice([300, 5000, 200000]) + b" = 1")
    else:
        keyed = [i for i, line in enumerate(lines) if b"=" in line and not line.lstrip().startswith(b"#")]
        i = rng.choice(keyed) if keyed else k
        key = lines[i].split(b"=", 1)[0] if b"=" in lines[i] else b"particles "
        value = rng.choice(HUGE_NUMBERS if kind == "huge" else GARBAGE_VALUES)
        lines[i] = key + b"= " + value.encode("utf-8", "surrogateescape")
    return b"\n".join(lines)


def mutate_parameters(rng, data):
    """One to three mutations of a parameter file's bytes."""
    for _ in range(rng.choice([1, 1, 2, 3])):
        kind = rng.choice(["flip", "byte", "truncate", "lines", "lines", "lines", "line_ends"])
        if not data:
            data = b"particles = 1\n"
        if kind == "flip":
            k = rng.randrange(len(data))
            data = data[:k] + bytes([data[k] ^ (1 << rng.randrange(8))]) + data[k + 1:]
        elif kind == "byte":
            k = rng.randrange(len(data))
            data = data[:k] + bytes([rng.randrange(256)]) + data[k + 1:]
        elif kind == "truncate":
            data = data[:rng.randrange(len(data))]
        elif kind == "line_ends":
            data = data.replace(b"\n", rng.choice(LINE_ENDS).encode())
            if rng.random() < 0.5:
                data = data.rstrip(b"\r\n")
        else:
            data = mutate_lines(rng, data)
    return data


def mutate_h5part(rng, data):
    """Byte flips, mostly in the first 4 KiB (superblock, root group, B-trees, object headers),
    some anywhere; sometimes a truncation."""
    data = bytearray(data)
    if rng.random() < 0.12:
        return bytes(data[:rng.randrange(len(data))])
    for _ in range(rng.choice([1, 1, 2, 4, 8])):
        head = min(len(data), 4096)
        k = rng.randrange(head) if rng.random() < 0.7 else rng.randrange(len(data))
        data[k] = data[k] ^ (1 << rng.randrange(8)) if rng.random() < 0.7 else rng.randrange(256)
    return bytes(data)


def limit_address_space():
    os.setsid()
    resource.setrlimit(resource.RLIMIT_AS, (ADDRESS_SPACE_LIMIT, ADDRESS_SPACE_LIMIT))


class runner:
    def __init__(self, options):
        self.options = options
        self.launcher = shlex.split(options.launcher)
        # ess_singleton_isolated: a singleton starts no orted daemon (Open MPI 4; ignored elsewhere).
        # Isolated singletons share one session directory under TMPDIR and remove it as they end,
        # so each run gets a TMPDIR of its own (run_once): concurrent cases do not collide.
        self.environment = dict(os.environ, OMP_NUM_THREADS="1", OMP_PROC_BIND="false",
                                OMPI_MCA_ess_singleton_isolated="1")
        self.quiet = ["--set", "progress_every=0", "--set", "diagnostics_every=0", "--no-timers"]

    def run(self, arguments, folder):
        """(status or 'timeout', stderr text) of one app run in `folder`. A run whose MPI runtime
        failed to start (exit 1 from MPI_Init_thread before the app reads anything: concurrent
        isolated singletons did so when they shared a session directory, before run_once gave each
        its own TMPDIR) is started once more."""
        status, error = self.run_once(arguments, folder)
        if status == 1 and "An error occurred in MPI_Init_thread" in error:
            status, error = self.run_once(arguments, folder)
        return status, error

    def run_once(self, arguments, folder):
        with tempfile.TemporaryDirectory(prefix="flecsph-fuzz-mpi-") as session:
            return self.run_in_session(arguments, folder, dict(self.environment, TMPDIR=session))

    def run_in_session(self, arguments, folder, environment):
        process = subprocess.Popen(self.launcher + arguments, cwd=folder, stdout=subprocess.DEVNULL,
                                   stderr=subprocess.PIPE, env=environment,
                                   preexec_fn=None if self.options.no_limit else limit_address_space,
                                   start_new_session=self.options.no_limit)
        try:
            _, error = process.communicate(timeout=self.options.timeout)
        except subprocess.TimeoutExpired:
            os.killpg(process.pid, signal.SIGKILL)  # the case's own process group only
            process.communicate()
            return "timeout", ""
        return process.returncode, error.decode("utf-8", "replace")


def earlier_output(folder, reference):
    path = os.path.join(folder, "earlier.h5part")
    shutil.copyfile(reference, path)
    return path


def same_bytes(a, b):
    with open(a, "rb") as x, open(b, "rb") as y:
        return x.read() == y.read()


def snapshot(paths):
    """The bytes of every regular file among `paths` (links followed), to see what a case lost."""
    kept = {}
    for path in paths:
        if os.path.isfile(path):
            with open(path, "rb") as f:
                kept[path] = f.read()
    return kept


# libhdf5 1.10 leaks free-list blocks when it fails on corrupted metadata (a failed H5Literate of a
# damaged link table, with every identifier closed) and then prints this at exit; it also frees
# garbage in H5G__link_release_table on that path and crashes the job. The readers therefore
# iterate no link table in the job (flecsi_lite/io/detail/h5part_precheck.hh): a corrupted file
# must end with a clean error and without this message.
LIBRARY_NOT_CLOSED = "infinite loop closing library"

# An error whose whole text is a library's bare word says nothing a user can act on.
UNCLEAR = re.compile(r"error: [a-z_]+: (stod|stoi|stol|stoul|stoll|stof|basic_string::\w+|std::\w+|vector::\w+)\s*$",
                     re.MULTILINE)
CLASSES = ("passed", "crash", "hang", "lost file", "bad exit status", "unclear error", "hdf5 not closed")


def judge(case, status, error, kept):
    """The failures of one finished case as (class, text) pairs; `kept` the files it must leave."""
    problems = []
    if status == "timeout":
        return [("hang", "no exit within the time limit (a hang)")]
    if status < 0 or status > 128:
        problems.append(("crash", "ended by signal %d" % (-status if status < 0 else status - 128)))
    elif status not in ALLOWED_STATUSES:
        problems.append(("bad exit status", "exit status %d (allowed: 0, 2, 3)" % status))
    if LIBRARY_NOT_CLOSED in error:
        problems.append(("hdf5 not closed", "HDF5 printed '%s' at exit" % LIBRARY_NOT_CLOSED))
    if status != 0:
        if not error.strip():
            problems.append(("unclear error", "non-zero exit without a message on stderr"))
        elif UNCLEAR.search(error):
            problems.append(("unclear error", "a bare library message: '%s'" % UNCLEAR.search(error).group(0)))
    for path, data in kept.items():
        if not os.path.isfile(path):
            problems.append(("lost file", "%s was removed" % os.path.basename(path)))
        else:
            with open(path, "rb") as f:
                if f.read() != data:
                    problems.append(("lost file", "%s was changed" % os.path.basename(path)))
    return problems


def prepare_inputs(options, work, run):
    """The reference output (any earlier run's), a tiny initial-data file and checkpoints of a
    global-step, an individual-step, a self-gravity and a fluid run (of the apps given)."""
    tiny = ["--set", "particles=40", "--set", "max_steps=2"]
    source = options.source
    sod_1d = os.path.join(source, "apps", "sod", "sod_1d.par")
    checkpoint = ["--set", "output_file=none", "--set", "checkpoint_every=1", "--set", "max_steps=2"]
    steps = [
        (options.sod, [sod_1d] + tiny + ["--set", "output_file=reference.h5part"]),
        (options.sod, [sod_1d] + tiny + ["--set", "output_file=initial.h5part"]),
        (options.sod, [sod_1d, "--set", "particles=40", "--set", "checkpoint_file=checkpoint.h5part"] + checkpoint),
        (options.sedov, [os.path.join(source, "apps", "sedov", "sedov_2d.par"), "--set", "particles_per_side=16",
                         "--set", "time_steps=individual", "--set", "checkpoint_file=individual.h5part"] + checkpoint),
    ]
    if options.evrard:
        steps.append((options.evrard, [os.path.join(source, "apps", "evrard", "evrard.par"), "--set", "particles=300",
                                       "--set", "checkpoint_file=gravity.h5part"] + checkpoint))
    if options.fluid:
        steps.append((options.fluid, [os.path.join(source, "apps", "fluid", "dam_break.par"), "--set", "particles=10",
                                      "--set", "checkpoint_file=fluid.h5part"] + checkpoint))
    for program, arguments in steps:
        status, error = run.run([program] + arguments + run.quiet, work)
        if status != 0:
            sys.exit("fuzz_inputs: preparing the inputs failed (%s): %s\n%s" % (status, " ".join(arguments), error))
    names = ["reference", "initial", "checkpoint", "individual"] + (["gravity"] if options.evrard else []) + \
        (["fluid"] if options.fluid else [])
    return {name: os.path.join(work, name + ".h5part") for name in names}


def parameter_case(options, files, n):
    rng = random.Random("%d parameters %d" % (options.seed, n))
    app, path = rng.choice(files)
    with open(path, "rb") as source:
        data = mutate_parameters(rng, small(os.path.basename(path), source.read()))
    return app, os.path.basename(path), data


def h5part_case(options, inputs, n):
    rng = random.Random("%d h5part %d" % (options.seed, n))
    which = rng.choice([name for name in inputs if name != "reference"])
    with open(inputs[which], "rb") as source:
        return which, mutate_h5part(rng, source.read())


# What each H5Part input is read by: the app, its parameter file and the keys that make it the
# run that wrote it (a restart must have the checkpoint's parameters).
def reader_of(options, which):
    apps = os.path.join(options.source, "apps")
    if which == "individual":
        return options.sedov, os.path.join(apps, "sedov", "sedov_2d.par"), \
            ["--set", "particles_per_side=16", "--set", "time_steps=individual"]
    if which == "gravity":
        return options.evrard, os.path.join(apps, "evrard", "evrard.par"), ["--set", "particles=300"]
    if which == "fluid":
        return options.fluid, os.path.join(apps, "fluid", "dam_break.par"), ["--set", "particles=10"]
    return options.sod, os.path.join(apps, "sod", "sod_1d.par"), ["--set", "particles=40"]


# Odd paths for the file keys and --trace: each a function of the case folder that prepares it
# and returns the text given. The parameter file is case.par; earlier.h5part the earlier output.
def odd_paths():
    def link_to(target):
        def make(folder):
            os.symlink(target, os.path.join(folder, "link.dat"))
            return "link.dat"
        return make

    def hard_link(folder):
        os.link(os.path.join(folder, "case.par"), os.path.join(folder, "hard.dat"))
        return "hard.dat"

    def fifo(folder):
        os.mkfifo(os.path.join(folder, "fifo.dat"))
        return "fifo.dat"

    def directory(folder):
        os.mkdir(os.path.join(folder, "folder.dat"))
        return "folder.dat"

    def long_folder(folder):
        deep = os.path.join("d" * 150, "e" * 100)
        os.makedirs(os.path.join(folder, deep))
        return os.path.join(deep, "x.dat")

    def fixed(text):
        return lambda folder: text

    return [("the parameter file", fixed("case.par")), ("./the parameter file", fixed("./case.par")),
            ("a link to the parameter file", link_to("case.par")), ("a hard link to the parameter file", hard_link),
            ("the earlier output", fixed("earlier.h5part")), ("the earlier output's .partial",
                                                              fixed("earlier.h5part.partial")),
            ("a link to the earlier output", link_to("earlier.h5part")), ("a dangling link", link_to("nowhere")),
            ("a fifo", fifo), ("a folder", directory), ("the working folder", fixed(".")), ("/", fixed("/")),
            ("a missing folder", fixed("missing/x.dat")), ("a 240-character name", fixed("n" * 233 + ".h5part")),
            ("a 260-character path", long_folder), ("a name with spaces", fixed("a b.dat")),
            ("a name with a newline", fixed("a\nb.dat")), ("a non-ASCII name", fixed("\u00fc\u00df.dat")),
            ("none", fixed("none")), ("auto", fixed("auto")), ("empty", fixed(""))]


PATH_KEYS = ["output_file", "checkpoint_file", "restart_file", "initial_data", "statistics_file",
             "used_parameters_file", "stop_file", "--trace"]


def path_case(options, n):
    rng = random.Random("%d paths %d" % (options.seed, n))
    return rng.choice(PATH_KEYS), rng.choice(odd_paths())


def run_case(options, run, inputs, files, kind, n):
    folder = os.path.join(options.work, "%s_%04d" % (kind, n))
    os.makedirs(folder, exist_ok=True)
    output = earlier_output(folder, inputs["reference"])
    bounded = ["--set", "max_steps=1", "--set", "output_file=earlier.h5part"] + run.quiet
    protected = [output]
    if kind == "parameters":
        app, name, data = parameter_case(options, files, n)
        with open(os.path.join(folder, "case.par"), "wb") as case_file:
            case_file.write(data)
        arguments = [getattr(options, app), "case.par"] + bounded
        what = "%s %s mutated" % (app, name)
    elif kind == "h5part":
        which, data = h5part_case(options, inputs, n)
        with open(os.path.join(folder, "case.h5part"), "wb") as case_file:
            case_file.write(data)
        program, parameters, keys = reader_of(options, which)
        # The checkpoints stopped at max_steps = 2: a restart takes one more step.
        key, steps = ("initial_data", "1") if which == "initial" else ("restart_file", "3")
        arguments = [program, parameters] + keys + ["--set", key + "=case.h5part"] + bounded + \
            ["--set", "max_steps=" + steps]
        what = "%s read as %s" % (which, key)
    else:
        key, (form, make) = path_case(options, n)
        shutil.copyfile(os.path.join(options.source, "apps", "sod", "sod_1d.par"), os.path.join(folder, "case.par"))
        path = make(folder)
        given = ["--trace", path] if key == "--trace" else ["--set", key + "=" + path]
        arguments = [options.sod, "case.par", "--set", "particles=40"] + bounded + given
        protected.append(os.path.join(folder, "case.par"))
        what = "%s = %s" % (key, form)
        # A run may legitimately write the earlier output only when output_file names it.
        if key == "output_file":
            protected.remove(output)
    kept = snapshot(protected)
    status, error = run.run(arguments, folder)
    if status == 0:
        kept.pop(output, None)  # a successful run replaces the earlier output of its name
    if kind == "paths" and key == "output_file" and status != 0 and os.path.isfile(output):
        # refused or failed: the earlier output must then be intact too
        kept[output] = open(inputs["reference"], "rb").read()
    problems = judge(n, status, error, kept)
    if not problems:
        shutil.rmtree(folder)
    return kind, n, what, status, error, problems, folder


def main():
    parser = argparse.ArgumentParser(description=__doc__)
    parser.add_argument("--sod", required=True)
    parser.add_argument("--sedov", required=True)
    for app in ("evrard", "cold-collapse", "fluid", "bns"):
        parser.add_argument("--" + app, default="", help="the %s app: its parameter files join the cases" % app)
    parser.add_argument("--source", required=True, help="source tree (its apps/*/*.par are mutated)")
    parser.add_argument("--work", required=True, help="scratch folder (emptied)")
    parser.add_argument("--seed", type=int, default=13)
    parser.add_argument("--parameter-cases", type=int, default=200)
    parser.add_argument("--h5part-cases", type=int, default=120)
    parser.add_argument("--path-cases", type=int, default=60)
    parser.add_argument("--timeout", type=float, default=30, help="seconds per case before it is a hang")
    parser.add_argument("--launcher", default="", help="command before the app, e.g. 'mpiexec -n 1' "
                        "(default: none, the app starts as an MPI singleton)")
    parser.add_argument("--jobs", type=int, default=2)
    parser.add_argument("--only", help="run only this case: parameters:N, h5part:N or paths:N")
    parser.add_argument("--no-limit", action="store_true", help="no address-space limit (sanitizer builds)")
    parser.add_argument("--allow-failures", action="store_true", help="report but exit 0 (for measurements)")
    options = parser.parse_args()
    for app in APPS:
        if getattr(options, app):
            setattr(options, app, os.path.abspath(getattr(options, app)))
    options.source, options.work = os.path.abspath(options.source), os.path.abspath(options.work)
    shutil.rmtree(options.work, ignore_errors=True)
    os.makedirs(options.work)

    run = runner(options)
    inputs = prepare_inputs(options, options.work, run)
    files = parameter_files(options)
    cases = [("parameters", n) for n in range(options.parameter_cases)] + \
            [("h5part", n) for n in range(options.h5part_cases)] + [("paths", n) for n in range(options.path_cases)]
    if options.only:
        kind, number = options.only.split(":")
        cases = [(kind, int(number))]
    statuses, classes, failures = {}, {}, []
    with concurrent.futures.ThreadPoolExecutor(max_workers=options.jobs) as pool:
        jobs = [pool.submit(run_case, options, run, inputs, files, kind, n) for kind, n in cases]
        for job in jobs:
            kind, n, what, status, error, problems, folder = job.result()
            statuses.setdefault(kind, {}).setdefault(status, 0)
            statuses[kind][status] += 1
            found = sorted({name for name, _ in problems}) or ["passed"]
            for name in found:
                classes.setdefault(kind, {}).setdefault(name, 0)
                classes[kind][name] += 1
            if problems:
                failures.append((kind, n, what, status, error, [text for _, text in problems], folder))
    for kind, counts in sorted(statuses.items()):
        print("fuzz_inputs: %s cases by exit status: %s" %
              (kind, ", ".join("%s: %d" % (s, c) for s, c in sorted(counts.items(), key=lambda x: str(x[0])))))
    for kind, counts in sorted(classes.items()):
        print("fuzz_inputs: %s cases by class: %s" %
              (kind, ", ".join("%s: %d" % (name, counts.get(name, 0)) for name in CLASSES)))
    for kind, n, what, status, error, problems, folder in failures:
        print("FAIL %s:%d (%s, exit %s; replay with --only %s:%d; files in %s): %s" %
              (kind, n, what, status, kind, n, folder, "; ".join(problems)))
        tail = error.strip().splitlines()[-6:]
        for line in tail:
            print("    " + line[:300])
    used = resource.getrusage(resource.RUSAGE_CHILDREN)
    print("fuzz_inputs: %d cases, %d failed (seed %d); %.0f CPU seconds in the cases" %
          (len(cases), len(failures), options.seed, used.ru_utime + used.ru_stime))
    return 1 if failures and not options.allow_failures else 0


if __name__ == "__main__":
    sys.exit(main())
