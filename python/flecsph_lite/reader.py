"""Reads one output time of FleCSPH-lite from an H5Part file or a SWIFT/GADGET snapshot.

Both give a Particles: `fluid` and `walls`, each a dict from snapshot dataset names (Coordinates
N x 3, Velocities, Masses, SmoothingLengths, Densities, InternalEnergies, Pressures, SoundSpeeds,
ParticleIDs, ...) to arrays; `time`, `dimension`, and `units` (grams, centimetres and seconds per
code unit). With unyt installed, the arrays carry their units: from the snapshots' per-dataset
attributes (U_M, U_L, U_t exponents and the Units group, as SWIFT writes them) or, for H5Part, from
the same exponents (unit_exponents) and the file's unit attributes ("Unit mass in cgs (U_M)", ...;
in files written before them, the unit keys of its `parameters` attribute).
"""
import re
from dataclasses import dataclass, field

import h5py
import numpy as np

try:
    import unyt
except ImportError:  # units are optional
    unyt = None

# H5Part dataset(s) -> snapshot dataset, as specialization/sph/files/snapshot_layout.hh maps them.
H5PART_TO_SNAPSHOT = {
    ("x", "y", "z"): "Coordinates",
    ("vx", "vy", "vz"): "Velocities",
    ("m",): "Masses",
    ("h",): "SmoothingLengths",
    ("rho",): "Densities",
    ("u",): "InternalEnergies",
    ("P",): "Pressures",
    ("cs",): "SoundSpeeds",
    ("id",): "ParticleIDs",
    ("du_dt",): "InternalEnergyRates",
    ("phi",): "Potentials",
}
# Wall particles are fixed: the snapshots hold no motion or heating of theirs.
NOT_FOR_WALLS = {"Velocities", "Accelerations", "InternalEnergyRates"}


def unit_exponents(name, dimension):
    """(mass, length, time) exponents of a snapshot quantity in `dimension` dimensions."""
    d = float(dimension)
    return {
        "Coordinates": (0, 1, 0), "Velocities": (0, 1, -1), "Masses": (1, 0, 0), "SmoothingLengths": (0, 1, 0),
        "Densities": (1, -d, 0), "InternalEnergies": (0, 2, -2), "Pressures": (1, 2 - d, -2),
        "SoundSpeeds": (0, 1, -1), "ParticleIDs": (0, 0, 0), "Accelerations": (0, 1, -2),
        "InternalEnergyRates": (0, 2, -3), "Potentials": (0, 2, -2),
    }.get(name)


@dataclass
class Particles:
    time: float
    dimension: int
    units: dict  # {"mass": grams, "length": cm, "time": s} per code unit
    fluid: dict = field(default_factory=dict)
    walls: dict = field(default_factory=dict)


def _with_units(values, exponents, units):
    if unyt is None or exponents is None or not np.issubdtype(values.dtype, np.floating):
        return values
    m, l, t = exponents
    factor = units["mass"] ** m * units["length"] ** l * units["time"] ** t
    unit = unyt.Unit("g") ** m * unyt.Unit("cm") ** l * unyt.Unit("s") ** t if (m, l, t) != (0, 0, 0) else None
    return unyt.unyt_array(values * factor, unit if unit is not None else "dimensionless")


def _first(value):
    value = np.asarray(value)
    return value.reshape(-1)[0] if value.size else value


def read_snapshot(path, with_units=True):
    """A SWIFT/GADGET-layout snapshot: PartType0 as `fluid`, PartType2 as `walls`."""
    with h5py.File(path, "r") as f:
        header = f["Header"].attrs
        dimension = int(_first(header["Dimension"]))
        units = {"mass": 1.0, "length": 1.0, "time": 1.0}
        if "Units" in f:
            u = f["Units"].attrs
            units = {"mass": float(_first(u["Unit mass in cgs (U_M)"])),
                     "length": float(_first(u["Unit length in cgs (U_L)"])),
                     "time": float(_first(u["Unit time in cgs (U_t)"]))}
        result = Particles(float(_first(header["Time"])), dimension, units)
        for group_name, target in (("PartType0", result.fluid), ("PartType2", result.walls)):
            if group_name not in f:
                continue
            for name, dataset in f[group_name].items():
                values = dataset[()]
                if with_units:
                    a = dataset.attrs
                    exponents = None
                    if "U_M exponent" in a:
                        # The dataset's own exponents: values times U_M^m U_L^l U_t^t is CGS.
                        exponents = tuple(float(_first(a[k])) for k in ("U_M exponent", "U_L exponent", "U_t exponent"))
                    values = _with_units(values, exponents, units)
                target[name] = values
    return result


def _parameter(text, key, default):
    match = re.search(rf"^{re.escape(key)}\s*=\s*([^\s#]+)", text, re.MULTILINE)
    return float(match.group(1)) if match else default


def h5part_steps(path):
    """The k of every Step#k group of an H5Part file, in increasing order (Step#10 after Step#9)."""
    with h5py.File(path, "r") as f:
        return sorted(int(k[5:]) for k in f.keys() if k.startswith("Step#"))


def _step_time(group):
    return float(group.attrs.get("TimeValue", group.attrs.get("time", 0.0)))


def h5part_step_times(path):
    """{k: time} of every Step#k group of an H5Part file, without reading its datasets."""
    with h5py.File(path, "r") as f:
        return {int(k[5:]): _step_time(f[k]) for k in f.keys() if k.startswith("Step#")}


def h5part_attributes(path):
    """The root attributes of an H5Part file (parameters, units, problem constants)."""
    with h5py.File(path, "r") as f:
        return {k: f.attrs[k] for k in f.attrs.keys()}


def read_h5part_step(path, step=None):
    """(time, {dataset: array}, {root attribute: value}) of Step#step as the file holds them, under
    the H5Part names (x, rho, kind, ...); the last step when None. ValueError for a file without
    steps or without that step."""
    steps = h5part_steps(path)
    if not steps:
        raise ValueError(f"{path} holds no Step#N group")
    step = steps[-1] if step is None else step
    if step not in steps:
        raise ValueError(f"{path} has no Step#{step} (steps: Step#{steps[0]} .. Step#{steps[-1]})")
    with h5py.File(path, "r") as f:
        group = f[f"Step#{step}"]
        data = {k: group[k][()] for k in group.keys()}
        time = _step_time(group)
        attributes = {k: f.attrs[k] for k in f.attrs.keys()}
    return time, data, attributes


def read_h5part(path, step=None, with_units=True):
    """Step#step of an H5Part file (the last when None), under the snapshot names."""
    time, data, attributes = read_h5part_step(path, step)
    parameters = attributes.get("parameters", b"")
    parameters = parameters.decode() if isinstance(parameters, bytes) else str(parameters)
    dimension = int(attributes.get("dimension", 3))
    # The unit system of the root attributes (SWIFT's names), or of the parameters in older files.
    units = {}
    for base, symbol in (("mass", "U_M"), ("length", "U_L"), ("time", "U_t")):
        attribute = f"Unit {base} in cgs ({symbol})"
        units[base] = float(attributes[attribute]) if attribute in attributes else \
            _parameter(parameters, f"unit_{base}_in_cgs", 1.0)
    result = Particles(time, dimension, units)
    kind = data.get("kind", np.zeros(len(data["x"]), dtype=np.int32))
    for sources, name in H5PART_TO_SNAPSHOT.items():
        if not all(s in data for s in sources):
            continue
        values = np.column_stack([data[s] for s in sources]) if len(sources) > 1 else data[sources[0]]
        for selected, target in ((kind == 0, result.fluid), (kind == 1, result.walls)):
            if selected.any() and not (target is result.walls and name in NOT_FOR_WALLS):
                chosen = values[selected]
                target[name] = _with_units(chosen, unit_exponents(name, dimension), units) if with_units else chosen
    return result


def read(path, **options):
    """read_h5part or read_snapshot, by what the file holds."""
    with h5py.File(path, "r") as f:
        is_snapshot = "Header" in f and "PartType0" in f
    return read_snapshot(path, **options) if is_snapshot else read_h5part(path, **options)
