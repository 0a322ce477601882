#!/usr/bin/env python3
# Compile time of the same sources in two configured build trees, interleaved (old, new, old,
# new, ...) so that both see the same load on a shared machine: user + system CPU seconds of each
# compile, and the ratio of the totals. Each tree's compile_commands.json gives the commands
# (CMake writes it: CMAKE_EXPORT_COMPILE_COMMANDS is on in this project); objects go to a
# scratch file, nothing in either tree changes.
#
#   scripts/compare_compile_times.py OLD_BUILD NEW_BUILD SOURCE_SUFFIX...
#   e.g. scripts/compare_compile_times.py /tmp/old/build build apps/sod/sod.cc tests/specialization/sph/density.cc
import json
import os
import resource
import subprocess
import sys
import tempfile


def commands(build, suffixes):
    found = {}
    with open(os.path.join(build, "compile_commands.json")) as f:
        for entry in json.load(f):
            for suffix in suffixes:
                if entry["file"].endswith(suffix):
                    found[suffix] = entry
    missing = [s for s in suffixes if s not in found]
    if missing:
        sys.exit(f"{build}/compile_commands.json has no source ending in: {', '.join(missing)}")
    return found


def compile_seconds(entry, scratch):
    # The same command with the object sent to the scratch file.
    command = entry["command"].split(" -o ")[0] + f" -o {scratch} -c {entry['file']}"
    before = resource.getrusage(resource.RUSAGE_CHILDREN)
    subprocess.run(command, shell=True, cwd=entry["directory"], check=True)
    after = resource.getrusage(resource.RUSAGE_CHILDREN)
    return after.ru_utime - before.ru_utime + after.ru_stime - before.ru_stime


def main():
    if len(sys.argv) < 4:
        sys.exit("usage: compare_compile_times.py OLD_BUILD NEW_BUILD SOURCE_SUFFIX...")
    old, new, suffixes = sys.argv[1], sys.argv[2], sys.argv[3:]
    trees = {"old": commands(old, suffixes), "new": commands(new, suffixes)}
    totals = {"old": 0.0, "new": 0.0}
    with tempfile.TemporaryDirectory() as scratch:
        for suffix in suffixes:
            for tag in ("old", "new"):
                seconds = compile_seconds(trees[tag][suffix], os.path.join(scratch, "unit.o"))
                totals[tag] += seconds
                print(f"{tag} {seconds:7.1f} s  {suffix}", flush=True)
    print(f"total old {totals['old']:.1f} s, new {totals['new']:.1f} s, new / old {totals['new'] / totals['old']:.3f}")


if __name__ == "__main__":
    main()
