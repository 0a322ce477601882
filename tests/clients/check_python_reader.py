"""Checks the Python package python/flecsph_lite on a run written with output_format = both: its
H5Part reader and its snapshot reader give the same arrays under the same names for every output
time (fluid and walls), with the same units when unyt is installed.

    python3 check_python_reader.py sod_1d.h5part
"""
import glob
import os
import re
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "python"))
import h5py  # noqa: E402
import numpy as np  # noqa: E402

import flecsph_lite  # noqa: E402

PROGRAM = "check_python_reader"


def main():
    path = sys.argv[1]
    stem = os.path.splitext(path)[0]
    snapshots = sorted(p for p in glob.glob(glob.escape(stem) + "_*.hdf5") if re.search(r"_\d{4,}\.hdf5$", p))
    with h5py.File(path, "r") as f:
        steps = sorted(int(k[5:]) for k in f.keys() if k.startswith("Step#"))
    failures = []
    if len(steps) != len(snapshots) or not steps:
        sys.exit(f"{PROGRAM}: {len(snapshots)} snapshots for {len(steps)} H5Part steps")
    for step, snapshot in zip(steps, snapshots):
        a, b = flecsph_lite.read_h5part(path, step), flecsph_lite.read(snapshot)
        if a.time != b.time or a.units != b.units or a.dimension != b.dimension:
            failures.append(f"{snapshot}: time, units or dimension differ from Step#{step}")
        for kind in ("fluid", "walls"):
            x, y = getattr(a, kind), getattr(b, kind)
            for name in x:
                if name not in y or not np.array_equal(np.asarray(x[name]), np.asarray(y[name])):
                    failures.append(f"{snapshot}: {kind} {name} differs from Step#{step}")
                elif str(getattr(x[name], "units", "")) != str(getattr(y[name], "units", "")):
                    failures.append(f"{snapshot}: {kind} {name} in {y[name].units}, H5Part in {x[name].units}")
        if not a.fluid:
            failures.append(f"Step#{step}: no fluid read")
    for failure in failures:
        print(f"{PROGRAM}: FAILED: {failure}")
    if failures:
        sys.exit(1)
    units = "with units (unyt)" if flecsph_lite.reader.unyt is not None else "without units (no unyt)"
    print(f"{PROGRAM}: {len(steps)} output times of {path} read alike from H5Part and snapshots, {units}")


if __name__ == "__main__":
    main()
