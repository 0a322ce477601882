"""Checks that splash plots density against x from the ASCII export of an H5Part file of ours.

    check_splash.py --tool build/apps/tools/h5part_to_ascii --splash /usr/bin/splash sod.h5part \\
        --output sod_rho.png

Exports the last step with apps/tools/h5part_to_ascii (Debian's splash cannot read HDF5), has
`splash -f ascii -x <x> -y <rho> -dev <png>` draw it, and compares what splash reports with the
file read by h5py: the time, the particle and column counts, the ranges of x and rho. The PNG
must be a picture of the right size with points drawn on it. Exits 1 naming what differs.
"""
import argparse
import math
import os
import re
import subprocess
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "apps", "plotting"))
import h5part_plot  # noqa: E402

PROGRAM = "check_splash"


def run(command):
    result = subprocess.run(command, stdin=subprocess.DEVNULL, capture_output=True, text=True)
    if result.returncode != 0:
        sys.exit(f"{PROGRAM}: {' '.join(command)} failed ({result.returncode}): {result.stderr}{result.stdout}")
    return result.stdout


def reported(pattern, text, what):
    """The numbers splash printed after `pattern`."""
    match = re.search(pattern + r"\s*=\s*([-+0-9.Ee]+)[,\s]+([-+0-9.Ee]+)?", text)
    if not match:
        sys.exit(f"{PROGRAM}: splash did not report {what}:\n{text}")
    return [float(g) for g in match.groups() if g is not None]


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("file")
    parser.add_argument("--tool", required=True, help="apps/tools/h5part_to_ascii")
    parser.add_argument("--splash", required=True)
    parser.add_argument("--output", required=True, help="PNG to write")
    args = parser.parse_args()

    time, data, _ = h5part_plot.read_step(args.file, None, PROGRAM)
    columns_file = os.path.splitext(args.output)[0] + ".dat"
    run([args.tool, args.file, "--output", columns_file])
    with open(columns_file) as f:
        labels = [f.readline(), f.readline()][1].lstrip("#").split()
    x_column, rho_column = labels.index("x") + 1, labels.index("rho") + 1
    if os.path.exists(args.output):
        os.remove(args.output)
    out = run([args.splash, "-f", "ascii", "-x", str(x_column), "-y", str(rho_column), "-dev", args.output,
               columns_file])

    failures = []
    splash_time = reported(r"setting time", out, "the time")[0]
    if not math.isclose(splash_time, time, rel_tol=1e-14):
        failures.append(f"time {splash_time}, the file's {time}")
    match = re.search(r"npts = (\d+), ncols = (\d+)", out)
    shape = (int(match.group(1)), int(match.group(2))) if match else None
    if shape != (len(data["x"]), len(labels)):
        failures.append(f"splash read (particles, columns) {shape}, the export has {(len(data['x']), len(labels))}")
    for name in ("x", "rho"):
        low, high = reported(rf"\n\s*{name} min, max", out, f"the range of {name}")
        expected = (float(data[name].min()), float(data[name].max()))
        if not all(math.isclose(a, b, rel_tol=1e-4) for a, b in zip((low, high), expected)):
            failures.append(f"{name} range {low} .. {high}, the file's {expected[0]} .. {expected[1]}")

    image = h5part_plot.pyplot().imread(args.output) if os.path.isfile(args.output) else None
    if image is None:
        failures.append(f"splash wrote no {args.output}")
    else:
        drawn = (image[:, :, :3] < 0.5).all(axis=2).mean()  # dark pixels: axes, labels, particles
        print(f"{PROGRAM}: {args.output}: {image.shape[1]}x{image.shape[0]}, {os.path.getsize(args.output)} bytes, "
              f"{drawn:.1%} of the pixels dark")
        if image.shape[0] < 200 or image.shape[1] < 200 or not 0.005 < drawn < 0.5:
            failures.append(f"{args.output} is not a plot ({image.shape}, {drawn:.2%} of the pixels dark)")
    for failure in failures:
        print(f"{PROGRAM}: FAILED: {failure}")
    if failures:
        sys.exit(1)
    print(f"{PROGRAM}: splash plotted rho (column {rho_column}) against x (column {x_column}) of "
          f"{shape[0]} particles at t = {splash_time} into {args.output}")


if __name__ == "__main__":
    main()
