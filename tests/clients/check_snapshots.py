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

# Snapshot dataset <- H5Part datasets (specialization/sph/files/snapshot_layout.hh).
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


def check_h5part_units(h5part, snapshot):
    """The H5Part file's unit attributes: the snapshot's unit system, and for each dataset the CGS
    factor and expression of the snapshot dataset it belongs to."""
    with h5py.File(h5part, "r") as f, h5py.File(snapshot, "r") as g:
        for name, symbol in (("mass", "U_M"), ("length", "U_L"), ("time", "U_t")):
            attribute = f"Unit {name} in cgs ({symbol})"
            require(attribute in f.attrs and f.attrs[attribute] == g["Units"].attrs[attribute][0],
                    f"{h5part}: root attribute '{attribute}' missing or not the snapshots' {name} unit")
        for name, sources in SOURCES.items():
            if name not in g["PartType0"]:
                continue
            dataset = g["PartType0"][name].attrs
            for source in sources:
                factor, units = f"{source} conversion factor to CGS", f"{source} CGS units"
                require(factor in f.attrs and f.attrs[factor] == dataset[UNIT_ATTRIBUTES[8]][0],
                        f"{h5part}: '{factor}' missing or not PartType0/{name}'s")
                require(units in f.attrs and f.attrs[units] == dataset["Expression for physical CGS units"],
                        f"{h5part}: '{units}' missing or not PartType0/{name}'s")


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


# pynbody's names of the SWIFT datasets (pynbody/snapshot/swift.py); the others keep theirs.
PYNBODY_NAMES = {"Coordinates": "pos", "Velocities": "vel", "Masses": "mass", "Densities": "rho",
                 "SmoothingLengths": "smooth", "InternalEnergies": "u", "Pressures": "p", "ParticleIDs": "iord"}


def cgs_unit(attributes, separator):
    """The dataset's CGS unit from its U_M, U_L, U_t exponents: "g*cm**-3" (separator "*")."""
    powers = [(symbol, float(attributes[f"U_{base} exponent"][0])) for symbol, base in (("g", "M"), ("cm", "L"), ("s", "t"))]
    text = separator.join(f"{symbol}**{power:g}" for symbol, power in powers if power != 0)
    return text or None


def client_arrays(client, path):
    """{dataset: (values in CGS as numpy, the client's unit)} of PartType0 as the client loads them."""
    with h5py.File(path, "r") as f:
        # Those the H5Part output holds (not Accelerations, which yt 4.4 loads without units).
        names = {name: dict(f["PartType0"][name].attrs) for name in f["PartType0"] if name in SOURCES}
    arrays = {}
    if client == "swiftsimio":
        import swiftsimio
        snapshot = swiftsimio.load(path)
        for name, attributes in names.items():
            values = getattr(snapshot.gas, re.sub(r"(?<=[a-z])(?=[A-Z])", "_", name).lower())
            unit = cgs_unit(attributes, "*")
            arrays[name] = (np.asarray(values.to_value(unit) if unit else values), str(values.units))
    elif client == "yt":
        import yt
        dataset = yt.load(path)
        require(type(dataset).__name__ == "SwiftDataset", f"yt read {path} as {type(dataset).__name__}")
        everything = dataset.all_data()
        for name, attributes in names.items():
            values = everything["PartType0", "Mass" if name == "Masses" else name]
            unit = cgs_unit(attributes, "*")
            if unit and values.units.is_dimensionless:
                # yt 4.4 gives units only to the fields its SWIFT frontend knows (not
                # InternalEnergyRates, SoundSpeeds): the file's values, in code units.
                arrays[name] = (np.asarray(values) * float(attributes[UNIT_ATTRIBUTES[8]][0]), "no unit in yt")
                continue
            arrays[name] = (np.asarray(values.to_value(unit) if unit else values), str(values.units))
    elif client == "pynbody":
        import pynbody
        snapshot = pynbody.load(path)
        require(type(snapshot).__name__ == "SwiftSnap", f"pynbody read {path} as {type(snapshot).__name__}")
        for name, attributes in names.items():
            values = snapshot.gas[PYNBODY_NAMES.get(name, name)]
            unit = cgs_unit(attributes, " ")
            arrays[name] = (np.asarray(values.in_units(unit) if unit else values), str(values.units))
    return arrays


def check_client(client, path, data):
    """The real reader loads the last snapshot: every PartType0 dataset it holds, converted to CGS
    by the reader from the file's units, equals the H5Part step's values times their CGS factor
    (bit for bit in code units of 1 g, 1 cm, 1 s)."""
    try:
        importlib.import_module(client)
    except ImportError as error:
        print(f"{PROGRAM}: {client} is not installed here ({error}): skipped")
        sys.exit(SKIP)
    kind = data.get("kind", np.zeros(len(data["x"]), dtype=np.int32))
    arrays = client_arrays(client, path)
    with h5py.File(path, "r") as f:
        factors = {name: float(f["PartType0"][name].attrs[UNIT_ATTRIBUTES[8]][0]) for name in f["PartType0"]}
    compared = []
    for name, (values, unit) in sorted(arrays.items()):
        sources = SOURCES.get(name)
        if sources is None or not all(s in data for s in sources):
            continue  # Accelerations: not in the H5Part output
        expected = np.column_stack([data[s] for s in sources]) if len(sources) > 1 else data[sources[0]]
        expected = expected[kind == 0]
        if np.issubdtype(expected.dtype, np.floating):
            expected = expected * factors[name]
        same = values.shape == expected.shape and (np.array_equal(values, expected) or (
            factors[name] != 1 and np.allclose(values, expected, rtol=1e-14, atol=0)))
        require(same, f"{client}: PartType0/{name} ({unit}) differs from the H5Part {sources} in CGS")
        compared.append(f"{name} [{unit}]")
    require(len(compared) >= 8, f"{client}: only {len(compared)} datasets compared")
    print(f"{PROGRAM}: {client} loads {path}: {len(kind[kind == 0])} gas particles; equal to the H5Part step: "
          + ", ".join(compared))
    if client == "yt":
        import yt
        picture = os.path.splitext(path)[0] + "_yt_projection.png"
        yt.ProjectionPlot(yt.load(path), "z", ("gas", "density")).save(picture)
        require(os.path.getsize(picture) > 0, f"yt wrote no {picture}")
        print(f"{PROGRAM}: yt: projection of ('gas', 'density') in {picture}")


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
        check_h5part_units(args.h5part, files[-1])
    if failures:
        sys.exit(f"{PROGRAM}: {len(failures)} failures")
    print(f"{PROGRAM}: {len(files)} snapshots of {args.h5part} {'load in ' + args.client if args.client else 'hold the H5Part values in the SWIFT layout, indexed'}")


if __name__ == "__main__":
    main()
