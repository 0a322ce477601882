"""Checks a run's SWIFT/GADGET snapshots against its H5Part output of the same run, with h5py only,
in the layout swiftsimio, yt, pynbody and splash read, and (--client) that those readers load them.

    python3 check_snapshots.py sod_1d.h5part                  # layout, values, units, XDMF index
    python3 check_snapshots.py sedov_3d.h5part --client yt    # exit 77 when yt is not installed

The layout checked is what the readers' source requires: swiftsimio (metadata/objects.py: Header
BoxSize, NumPart_Total, Dimension, Time; Units "Unit ... in cgs (U_x)"; per dataset "U_M exponent"
... and "Conversion factor to CGS (not including cosmological corrections)"), yt
(frontends/swift/data_structures.py: Header Code == "SWIFT", Dimension, BoxSize, Time; groups
Policy "cosmological integration", Parameters "InitialConditions:periodic", HydroScheme,
SubgridScheme), pynbody (snapshot/swift.py: a Policy group marks SWIFT; Units group), splash
(read_data_gadget_hdf5: Header NumPart_ThisFile, MassTable, Time; PartTypeN/Coordinates N x 3,
SmoothingLengths, Masses, Densities). Every snapshot's values must equal the H5Part step of its
time bit for bit. Exits 1 naming what differs.
"""
import argparse
import glob
import importlib
import os
import re
import sys
import xml.etree.ElementTree as ElementTree

import h5py
import numpy as np

PROGRAM = "check_snapshots"
SKIP = 77
failures = []

# Snapshot dataset <- H5Part datasets (specialization/sph/snapshot_layout.hh).
SOURCES = {"Coordinates": ("x", "y", "z"), "Velocities": ("vx", "vy", "vz"), "Masses": ("m",),
           "SmoothingLengths": ("h",), "Densities": ("rho",), "InternalEnergies": ("u",), "Pressures": ("P",),
           "SoundSpeeds": ("cs",), "ParticleIDs": ("id",), "InternalEnergyRates": ("du_dt",), "Potentials": ("phi",)}
UNIT_ATTRIBUTES = ["U_M exponent", "U_L exponent", "U_t exponent", "U_I exponent", "U_T exponent",
                   "h-scale exponent", "a-scale exponent", "Expression for physical CGS units",
                   "Conversion factor to CGS (not including cosmological corrections)",
                   "Conversion factor to physical CGS (including cosmological corrections)", "Description"]


def require(condition, message):
    if not condition:
        failures.append(message)
        print(f"{PROGRAM}: FAILED: {message}")
    return condition


def h5part_steps(path):
    with h5py.File(path, "r") as f:
        steps = sorted(int(k[5:]) for k in f.keys() if k.startswith("Step#"))
        return [(float(f[f"Step#{k}"].attrs["TimeValue"]), {n: f[f"Step#{k}"][n][()] for n in f[f"Step#{k}"]})
                for k in steps]


def snapshot_files(h5part):
    stem = os.path.splitext(h5part)[0]
    return sorted(p for p in glob.glob(glob.escape(stem) + "_*.hdf5") if re.search(r"_\d{4,}\.hdf5$", p))


def check_layout(path, time, data):
    """One snapshot against the H5Part step of the same time."""
    with h5py.File(path, "r") as f:
        header = f["Header"].attrs
        require(header["Code"] == b"SWIFT", f"{path}: Header/Code is {header['Code']!r}, not b'SWIFT' (yt's mark)")
        for name in ("BoxSize", "NumPart_ThisFile", "NumPart_Total", "NumPart_Total_HighWord", "MassTable", "Time",
                     "Redshift", "Dimension", "NumFilesPerSnapshot", "Flag_Entropy_ICs", "Flag_DoublePrecision"):
            require(name in header, f"{path}: Header has no {name}")
        require(header["BoxSize"].shape == (3,), f"{path}: BoxSize is not 3 numbers")
        require(header["Time"][0] == time, f"{path}: Header/Time {header['Time'][0]!r} is not the step's {time!r}")
        kind = data.get("kind", np.zeros(len(data["x"]), dtype=np.int32))
        counts = header["NumPart_ThisFile"]
        require(counts[0] == np.count_nonzero(kind == 0) and counts[2] == np.count_nonzero(kind == 1),
                f"{path}: NumPart_ThisFile {list(counts)} is not the H5Part step's fluid and wall counts")
        require(np.array_equal(header["NumPart_Total"], counts) and not header["NumPart_Total_HighWord"].any(),
                f"{path}: NumPart_Total (or its high word) differs from NumPart_ThisFile")
        for group in ("Units", "InternalCodeUnits"):
            for unit in ("mass", "length", "time", "current", "temperature"):
                symbol = {"mass": "U_M", "length": "U_L", "time": "U_t", "current": "U_I", "temperature": "U_T"}[unit]
                require(f"Unit {unit} in cgs ({symbol})" in f[group].attrs, f"{path}: {group} lacks the {unit} unit")
        for group in ("Policy", "Parameters", "HydroScheme", "SubgridScheme", "Cosmology", "Code"):
            require(group in f, f"{path}: no group {group}")
        require("cosmological integration" in f["Policy"].attrs, f"{path}: Policy lacks 'cosmological integration'")
        require("InitialConditions:periodic" in f["Parameters"].attrs, f"{path}: Parameters lacks InitialConditions:periodic")
        require(f["Code"].attrs["Code"] == b"FleCSPH-lite", f"{path}: Code/Code does not name the writer")
        unit_length = f["Units"].attrs["Unit length in cgs (U_L)"][0]
        for part_type, selected in (("PartType0", kind == 0), ("PartType2", kind == 1)):
            if not selected.any():
                require(part_type not in f, f"{path}: {part_type} written without particles")
                continue
            group = f[part_type]
            for name, sources in SOURCES.items():
                if name not in group:
                    require(name in ("Velocities", "Potentials", "InternalEnergyRates") or not all(s in data for s in sources),
                            f"{path}: {part_type} has no {name}")
                    continue
                dataset = group[name]
                expected = np.column_stack([data[s] for s in sources]) if len(sources) > 1 else data[sources[0]]
                expected = expected[selected]
                require(dataset.shape == expected.shape, f"{path}: {part_type}/{name} is {dataset.shape}, not {expected.shape}")
                require(dataset.dtype == expected.dtype and np.array_equal(dataset[()], expected),
                        f"{path}: {part_type}/{name} differs from the H5Part datasets {sources}")
                for attribute in UNIT_ATTRIBUTES:
                    require(attribute in dataset.attrs, f"{path}: {part_type}/{name} lacks attribute '{attribute}'")
            coordinates = group["Coordinates"].attrs
            require(coordinates["U_L exponent"][0] == 1 and coordinates["U_M exponent"][0] == 0,
                    f"{path}: {part_type}/Coordinates is not a length")
            require(coordinates["Conversion factor to CGS (not including cosmological corrections)"][0] == unit_length,
                    f"{path}: {part_type}/Coordinates' CGS factor is not the unit of length")
            require(group["Coordinates"].shape[1] == 3, f"{path}: Coordinates not N x 3")


def check_index(h5part, files, times):
    """<stem>.xdmf lists every snapshot, at its time, with its datasets."""
    index = os.path.splitext(h5part)[0] + ".xdmf"
    if not require(os.path.isfile(index), f"no XDMF index {index}"):
        return
    root = ElementTree.parse(index).getroot()
    series = root.find("Domain/Grid")
    steps = series.findall("Grid")
    require(len(steps) == len(files), f"{index}: {len(steps)} time steps for {len(files)} snapshots")
    for step, path, time in zip(steps, files, times):
        value = float(step.find("Time").get("Value"))
        require(value == time, f"{index}: time {value!r} for {path}, not {time!r}")
        for item in step.iter("DataItem"):
            file_name, dataset = item.text.split(":", 1)
            target = os.path.join(os.path.dirname(index), file_name)
            with h5py.File(target, "r") as f:
                if require(dataset in f, f"{index}: {item.text} does not exist"):
                    shape = tuple(int(n) for n in item.get("Dimensions").split())
                    require(f[dataset].shape == shape, f"{index}: {item.text} is {f[dataset].shape}, not {shape}")


def check_client(client, path, data):
    """The real reader loads the last snapshot with the H5Part step's values and units."""
    try:
        importlib.import_module(client)
    except ImportError as error:
        print(f"{PROGRAM}: {client} is not installed here ({error}): skipped")
        sys.exit(SKIP)
    kind = data.get("kind", np.zeros(len(data["x"]), dtype=np.int32))
    rho = data["rho"][kind == 0]
    if client == "swiftsimio":
        import swiftsimio
        snapshot = swiftsimio.load(path)
        densities = snapshot.gas.densities
        require(np.array_equal(np.asarray(densities), rho), "swiftsimio: gas densities differ from rho")
        require(str(snapshot.gas.coordinates.units) == "cm", f"swiftsimio: coordinates in {snapshot.gas.coordinates.units}")
        dimension = int(snapshot.metadata.dimension[0]) if np.ndim(snapshot.metadata.dimension) else int(snapshot.metadata.dimension)
        print(f"{PROGRAM}: swiftsimio: {snapshot.metadata.n_gas} gas particles at t = {snapshot.metadata.time}, "
              f"densities in {densities.units}, {dimension}D")
    elif client == "yt":
        import yt
        dataset = yt.load(path)
        require(type(dataset).__name__ == "SwiftDataset", f"yt read {path} as {type(dataset).__name__}")
        loaded = dataset.all_data()["PartType0", "Densities"]
        require(np.array_equal(np.asarray(loaded), rho), "yt: PartType0 Densities differ from rho")
        picture = os.path.splitext(path)[0] + "_yt_projection.png"
        plot = yt.ProjectionPlot(dataset, "z", ("gas", "density"))
        plot.save(picture)
        require(os.path.getsize(picture) > 0, f"yt wrote no {picture}")
        print(f"{PROGRAM}: yt: SwiftDataset at t = {dataset.current_time}, {len(loaded)} gas particles, "
              f"density in {loaded.units}; projection {picture}")
    elif client == "pynbody":
        import pynbody
        snapshot = pynbody.load(path)
        require(type(snapshot).__name__ == "SwiftSnap", f"pynbody read {path} as {type(snapshot).__name__}")
        require(np.array_equal(np.asarray(snapshot.gas["rho"]), rho), "pynbody: gas rho differs from the H5Part rho")
        print(f"{PROGRAM}: pynbody: SwiftSnap, {len(snapshot.gas)} gas particles, rho in {snapshot.gas['rho'].units}")


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("h5part", help="the H5Part output of a run with output_format = both")
    parser.add_argument("--client", choices=["swiftsimio", "yt", "pynbody"])
    args = parser.parse_args()
    steps = h5part_steps(args.h5part)
    files = snapshot_files(args.h5part)
    if not require(len(files) == len(steps), f"{len(files)} snapshots beside {args.h5part} for {len(steps)} steps"):
        sys.exit(1)
    if args.client:
        check_client(args.client, files[-1], steps[-1][1])
    else:
        for path, (time, data) in zip(files, steps):
            check_layout(path, time, data)
        check_index(args.h5part, files, [time for time, _ in steps])
    if failures:
        sys.exit(f"{PROGRAM}: {len(failures)} failures")
    print(f"{PROGRAM}: {len(files)} snapshots of {args.h5part} {'load in ' + args.client if args.client else 'hold the H5Part values in the SWIFT layout, indexed'}")


if __name__ == "__main__":
    main()
