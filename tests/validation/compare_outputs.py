#!/usr/bin/env python3
"""Compares two folders of app outputs bit for bit (scripts/compare_app_outputs.sh compare).

Every file of the first folder must exist in the second and the reverse. HDF5 files: the same
groups, datasets and attributes, every dataset's bytes and element type equal, every attribute
equal, except the stamps of the build that wrote them (program version, git commit). Text files:
equal line by line, except lines that carry those stamps or wall-clock seconds. The last step of
each H5Part file is compared again with compare_h5part when its path is given.

    /usr/bin/python3 compare_outputs.py BASELINE OUTPUT [--compare-h5part PATH]

Exit status 0 when everything is equal, 1 when something differs (each difference printed).
"""
import argparse
import os
import re
import subprocess
import sys

import h5py
import numpy

# What a build stamps on its output: its version and git commit, and the run's wall-clock time.
STAMP = re.compile(r"git |\(git|version|wall[- _]?(clock|time)|seconds|elapsed|\bs/step", re.IGNORECASE)
# The lines of an app's standard output that state results ("sod: L1 errors ...", "conserved:
# ..."), not the executor's timing summary ("sph: ... particle-steps/s") or the progress lines.
RESULT_LINE = re.compile(r"^(?!sph:)[a-z_]+: ")
# Attributes that hold nothing but such a stamp (SWIFT's "Git Revision" of the Code group).
STAMP_ATTRIBUTE = re.compile(r"git|version", re.IGNORECASE)
HDF5_SUFFIXES = (".h5part", ".hdf5", ".h5", ".partial")


def stamped(text):
    return bool(STAMP.search(text))


def attribute_text(value):
    if isinstance(value, bytes):
        return value.decode("utf-8", "replace")
    return str(value)


def compare_attributes(name, a, b, problems):
    keys_a, keys_b = set(a.attrs.keys()), set(b.attrs.keys())
    for key in sorted(keys_a ^ keys_b):
        problems.append(f"{name}: attribute '{key}' in only one file")
    for key in sorted(keys_a & keys_b):
        if STAMP_ATTRIBUTE.search(key):
            continue
        x, y = a.attrs[key], b.attrs[key]
        if isinstance(x, numpy.ndarray) or isinstance(y, numpy.ndarray):
            x, y = numpy.asarray(x), numpy.asarray(y)
            if x.dtype != y.dtype or x.shape != y.shape or x.tobytes() != y.tobytes():
                problems.append(f"{name}: attribute '{key}' differs")
            continue
        tx, ty = attribute_text(x), attribute_text(y)
        if tx == ty:
            continue
        lines_x = [line for line in tx.splitlines() if not stamped(line)]
        lines_y = [line for line in ty.splitlines() if not stamped(line)]
        if lines_x != lines_y or not (stamped(tx) or stamped(ty)):
            problems.append(f"{name}: attribute '{key}' differs: {tx[:120]!r} != {ty[:120]!r}")


def compare_hdf5(path_a, path_b, problems):
    """Every object of both files, bit for bit; returns the number of datasets compared."""
    datasets = 0
    with h5py.File(path_a, "r") as a, h5py.File(path_b, "r") as b:
        names_a, names_b = [], []
        a.visit(names_a.append)
        b.visit(names_b.append)
        for name in sorted(set(names_a) ^ set(names_b)):
            problems.append(f"{path_b}: '{name}' in only one file")
        compare_attributes(f"{path_b}:/", a, b, problems)
        for name in sorted(set(names_a) & set(names_b)):
            x, y = a[name], b[name]
            if isinstance(x, h5py.Dataset) != isinstance(y, h5py.Dataset):
                problems.append(f"{path_b}:{name}: a dataset in one file only")
                continue
            compare_attributes(f"{path_b}:{name}", x, y, problems)
            if not isinstance(x, h5py.Dataset):
                continue
            datasets += 1
            if x.dtype != y.dtype or x.shape != y.shape:
                problems.append(f"{path_b}:{name}: {x.dtype}{x.shape} != {y.dtype}{y.shape}")
            elif numpy.asarray(x[()]).tobytes() != numpy.asarray(y[()]).tobytes():
                problems.append(f"{path_b}:{name}: values differ")
    return datasets


def compare_text(path_a, path_b, problems, keep=None):
    """Line by line, less the stamped lines (and, with `keep`, the lines it does not match)."""

    def lines(stream):
        return [line for line in stream.read().splitlines()
                if not stamped(line) and (keep is None or keep.match(line))]

    with open(path_a, errors="replace") as a, open(path_b, errors="replace") as b:
        lines_a, lines_b = lines(a), lines(b)
    if lines_a != lines_b:
        for x, y in zip(lines_a, lines_b):
            if x != y:
                problems.append(f"{path_b}: line differs: {x[:100]!r} != {y[:100]!r}")
                return
        problems.append(f"{path_b}: {len(lines_a)} lines != {len(lines_b)} lines")


def files_under(folder):
    found = set()
    for directory, _, names in os.walk(folder):
        for name in names:
            found.add(os.path.relpath(os.path.join(directory, name), folder))
    return found


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("baseline")
    parser.add_argument("output")
    parser.add_argument("--compare-h5part", help="the compare_h5part program (last steps again)")
    arguments = parser.parse_args()
    files_a, files_b = files_under(arguments.baseline), files_under(arguments.output)
    problems = [f"{name}: in only one folder" for name in sorted(files_a ^ files_b)]
    counts = {"hdf5": 0, "datasets": 0, "text": 0, "last steps": 0, "stdout results": 0}
    for name in sorted(files_a & files_b):
        path_a = os.path.join(arguments.baseline, name)
        path_b = os.path.join(arguments.output, name)
        if name.endswith("stdout.txt"):  # the results the app prints; not its timings
            counts["stdout results"] += 1
            compare_text(path_a, path_b, problems, RESULT_LINE)
            continue
        if name.endswith(HDF5_SUFFIXES) and h5py.is_hdf5(path_a):
            counts["hdf5"] += 1
            counts["datasets"] += compare_hdf5(path_a, path_b, problems)
            if arguments.compare_h5part and name.endswith(".h5part"):
                result = subprocess.run([arguments.compare_h5part, path_a, path_b], capture_output=True, text=True)
                counts["last steps"] += 1
                if result.returncode != 0:
                    problems.append(f"{name}: compare_h5part: {result.stdout.strip()} {result.stderr.strip()}")
        else:
            counts["text"] += 1
            compare_text(path_a, path_b, problems)
    for problem in problems:
        print("DIFFERS:", problem)
    summary = ", ".join(f"{value} {key}" for key, value in counts.items())
    print(f"compared {len(files_a & files_b)} files ({summary}): "
          + ("all bitwise identical" if not problems else f"{len(problems)} differences"))
    return 1 if problems else 0


if __name__ == "__main__":
    sys.exit(main())
