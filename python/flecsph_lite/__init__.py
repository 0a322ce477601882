"""Readers of FleCSPH-lite's outputs: H5Part series (one file, Step#k groups) and SWIFT/GADGET-layout
snapshots (one `<stem>_NNNN.hdf5` per output time), as numpy arrays under the snapshot names
(Coordinates, Densities, ...), with their units when unyt is installed.

    import flecsph_lite
    step = flecsph_lite.read("sod_1d.h5part")          # the last step
    snap = flecsph_lite.read("sod_1d_0004.hdf5")       # the same particles, same values
    snap.fluid["Densities"], snap.time, snap.units      # unyt arrays when unyt is available
    time, data, attributes = flecsph_lite.read_h5part_step("sod_1d.h5part", 3)  # H5Part names, as stored
"""
from .reader import (Particles, read, read_h5part, read_snapshot, h5part_steps, read_h5part_step,
                     h5part_step_times, h5part_attributes,
                     H5PART_TO_SNAPSHOT)

__all__ = ["Particles", "read", "read_h5part", "read_snapshot", "h5part_steps", "read_h5part_step",
           "h5part_step_times", "h5part_attributes",
           "H5PART_TO_SNAPSHOT"]
