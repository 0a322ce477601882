"""What the plot scripts share: reading H5Part steps (through python/flecsph_lite), their command
line, the exact-solution program.

apps/sod/plot_sod.py and apps/sedov/plot_sedov.py put this folder on sys.path and import it; a
reader and a figure are all a new plot script has to add.
"""
import argparse
import csv
import io
import os
import re
import subprocess
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "python"))  # the package, installed or not
import flecsph_lite  # noqa: E402
DEFAULT_EXACT = os.path.join(HERE, "..", "..", "build", "apps", "exact", "exact_solution")


def step_indices(path, program):
    """The k of every Step#k group of an H5Part file, in increasing order."""
    indices = flecsph_lite.h5part_steps(path)
    if not indices:
        sys.exit(f"{program}: {path} holds no Step#N group")
    return indices


def read_step(path, step, program):
    """Returns (time, {dataset: array}, root attributes) of Step#step, the last step when None
    (python/flecsph_lite's reader, the one every script and test reads our files with)."""
    try:
        return flecsph_lite.read_h5part_step(path, step)
    except ValueError as error:
        sys.exit(f"{program}: {error}")


def attributes(path, program):
    """The root attributes of an H5Part file (its parameters, units and problem constants)."""
    try:
        return flecsph_lite.h5part_attributes(path)
    except OSError as error:
        sys.exit(f"{program}: cannot read {path}: {error}")


def step_times(path, program):
    """{k: time} of every Step#k of an H5Part file (no datasets read); exits when it has none."""
    try:
        times = flecsph_lite.h5part_step_times(path)
    except OSError as error:
        sys.exit(f"{program}: cannot read {path}: {error}")
    if not times:
        sys.exit(f"{program}: {path} holds no Step#N group")
    return times


def number(attributes, key, default):
    """A numeric root attribute as a float (HDF5 tools may store scalars as 1-element arrays), or
    else the value of the parameter `key` in the file's resolved parameters (its `parameters`
    attribute, where a problem's keys are: rho_left, blast_energy, ...), or else `default`."""
    if key in attributes:
        value = attributes[key]
        if hasattr(value, "__len__"):
            value = value[0]
        return float(value)
    text = attributes.get("parameters", b"")
    text = text.decode() if isinstance(text, bytes) else str(text)
    match = re.search(rf"^{re.escape(key)}\s*=\s*([^\s#]+)", text, re.MULTILINE)
    return float(match.group(1)) if match else float(default)


def command_line(description):
    """The options every plot script takes: the file, --step, --output and --exact."""
    parser = argparse.ArgumentParser(description=description,
                                     formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("file", help="H5Part file written by the app")
    parser.add_argument("--step", type=int, help="index k of Step#k (default: the last step)")
    parser.add_argument("--output", help="PNG to write (default: the file's name with .png)")
    parser.add_argument("--exact", default=DEFAULT_EXACT, help="the exact_solution program")
    return parser


def exact_solution(exact, arguments, program):
    """Runs apps/exact/exact_solution with `arguments` and returns its CSV columns as arrays."""
    command = [exact] + [str(a) for a in arguments]
    result = subprocess.run(command, capture_output=True, text=True)
    if result.returncode != 0:
        sys.exit(f"{program}: {' '.join(command)} failed: {result.stderr.strip()}")
    rows = list(csv.DictReader(io.StringIO(result.stdout)))
    return {k: np.array([float(r[k]) for r in rows]) for k in rows[0].keys()}


def pyplot():
    """matplotlib.pyplot drawing to files only (no display needed)."""
    import matplotlib

    matplotlib.use("Agg")
    import matplotlib.pyplot as plt

    return plt


def save(figure, args, dpi):
    """Writes the figure to --output, or next to the input file, and says where."""
    output = args.output or os.path.splitext(args.file)[0] + ".png"
    figure.savefig(output, dpi=dpi)
    print(f"plot written to {output}")
    return output
