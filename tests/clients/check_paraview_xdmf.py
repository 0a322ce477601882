"""Checks that ParaView opens a run's XDMF snapshot index (<stem>.xdmf) as a time series: one time
per snapshot (their Header/Time), and at each the fluid particles (PartType0) at their Coordinates
with their datasets as point arrays holding the snapshot's values.

    pvpython check_paraview_xdmf.py sod_1d.xdmf

Exits 1 naming what differs.
"""
import glob
import os
import re
import sys

import h5py
import numpy as np
from paraview import simple
from vtkmodules.numpy_interface import dataset_adapter

PROGRAM = "check_paraview_xdmf"
failures = []


def require(condition, message):
    if not condition:
        failures.append(message)
        print(f"{PROGRAM}: FAILED: {message}")
    return condition


def fluid_block(output):
    """The PartType0 grid of ParaView's output at one time (a multiblock of the spatial collection)."""
    data = output.VTKObject
    if data.IsA("vtkMultiBlockDataSet") or data.IsA("vtkPartitionedDataSetCollection"):
        iterator = data.NewIterator()
        iterator.InitTraversal()
        while not iterator.IsDoneWithTraversal():
            name = iterator.GetCurrentMetaData().Get(data.NAME()) if iterator.GetCurrentMetaData() else ""
            if name == "PartType0":
                return dataset_adapter.WrapDataObject(iterator.GetCurrentDataObject())
            iterator.GoToNextItem()
        iterator.InitTraversal()
        return dataset_adapter.WrapDataObject(iterator.GetCurrentDataObject())
    return output


def main():
    index = sys.argv[1]
    stem = os.path.splitext(index)[0]
    files = sorted(p for p in glob.glob(glob.escape(stem) + "_*.hdf5") if re.search(r"_\d{4,}\.hdf5$", p))
    times = []
    for path in files:
        with h5py.File(path, "r") as f:
            times.append(float(f["Header"].attrs["Time"][0]))
    reader = simple.XDMFReader(FileNames=[index])
    require(list(reader.TimestepValues) == times,
            f"ParaView's TimestepValues {list(reader.TimestepValues)} are not the snapshots' times {times}")
    for path, time in zip(files, times):
        simple.UpdatePipeline(time=time, proxy=reader)
        block = fluid_block(dataset_adapter.WrapDataObject(reader.GetClientSideObject().GetOutputDataObject(0)))
        with h5py.File(path, "r") as f:
            group = f["PartType0"]
            points = block.GetNumberOfPoints()
            if not require(points == group["Coordinates"].shape[0],
                           f"{path}: ParaView sees {points} points, the file {group['Coordinates'].shape[0]}"):
                continue
            require(np.array_equal(np.asarray(block.Points), group["Coordinates"][()]),
                    f"{path}: the points are not at the Coordinates")
            for name in ("Densities", "Pressures", "Velocities", "SmoothingLengths"):
                if require(name in block.PointData.keys(), f"{path}: no point array {name}"):
                    require(np.array_equal(np.asarray(block.PointData[name]), group[name][()]),
                            f"{path}: point array {name} differs from the file")
        print(f"{PROGRAM}: {path} at t = {time!r}: {points} points, point arrays {' '.join(sorted(block.PointData.keys()))}")
    if failures:
        sys.exit(f"{PROGRAM}: ParaView does not read {index} as written ({len(failures)} failures)")
    print(f"{PROGRAM}: ParaView's XDMF reader opens {index}: {len(files)} snapshots, TimestepValues {times}")


if __name__ == "__main__":
    main()
