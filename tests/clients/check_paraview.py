"""Checks that ParaView's H5PartReader reads a Sod run of ours as the file holds it, and saves a
screenshot of the particles coloured by density, as a person would first look at the file.

    pvpython --force-offscreen-rendering check_paraview.py sod.h5part --screenshot sod.png

The file is read independently with h5py (apps/plotting/h5part_plot.py). ParaView must offer one
time per step (the steps' TimeValue attributes), and at each of them one point per particle at
(x, y, z) with every dataset of the step as a point array holding the same values. The screenshot
must show the tube: warm colours (high density) left of cool ones. Exits 1 naming what differs.

Debian's ParaView renders through X even offscreen: without $DISPLAY (or with --xvfb), the script
renders on a private Xvfb server that it starts and stops itself.
"""
import argparse
import contextlib
import ctypes
import os
import shutil
import signal
import subprocess
import sys

import numpy as np
from paraview import simple
from vtkmodules.numpy_interface import dataset_adapter
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkCommonDataModel import vtkDataObject
from vtkmodules.vtkIOImage import vtkPNGReader

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "apps", "plotting"))
import h5part_plot  # noqa: E402

PROGRAM = "check_paraview"
failures = []


def require(condition, message):
    if not condition:
        failures.append(message)
        print(f"{PROGRAM}: FAILED: {message}")
    return condition


def check_step(reader, step, time, data):
    """ParaView's output at `time` against the file's Step#step; returns (points, arrays) if equal."""
    failures_before = len(failures)
    simple.UpdatePipeline(time=time, proxy=reader)
    output = dataset_adapter.WrapDataObject(reader.GetClientSideObject().GetOutputDataObject(0))
    shown_time = output.GetInformation().Get(vtkDataObject.DATA_TIME_STEP())
    require(shown_time == time, f"Step#{step}: ParaView shows time {shown_time}, not {time}")
    particles = len(next(iter(data.values())))
    points = output.GetNumberOfPoints()
    if not require(points == particles, f"Step#{step}: ParaView sees {points} points, the file {particles} particles"):
        return None
    if require({"x", "y", "z"} <= set(data), f"Step#{step}: the file has no x, y, z datasets"):
        positions = np.column_stack([data[k] for k in ("x", "y", "z")])
        require(np.array_equal(output.Points, positions.astype(output.Points.dtype)),
                f"Step#{step}: the points are not at (x, y, z) of the file")
    arrays = set(output.PointData.keys())
    require(arrays == set(data), f"Step#{step}: ParaView's point arrays {sorted(arrays)} are not the "
                                 f"file's datasets {sorted(data)}")
    for name in sorted(arrays & set(data)):
        values = output.PointData[name]
        require(np.array_equal(values, data[name]), f"Step#{step}: point array {name} differs from the file "
                f"(ParaView range {np.min(values)} .. {np.max(values)}, file {data[name].min()} .. {data[name].max()})")
    return (points, arrays) if len(failures) == failures_before else None


def screenshot(reader, time, path, title):
    """The particles at `time` coloured by rho, with a colour bar, on a white background."""
    view = simple.CreateView("RenderView")
    width, height = 1200, 500
    view.ViewSize = [width, height]
    view.OrientationAxesVisibility = 0
    view.UseColorPaletteForBackground = 0
    view.Background = [1.0, 1.0, 1.0]
    view.ViewTime = time
    display = simple.Show(reader, view)
    display.SetRepresentationType("Points")
    display.PointSize = 5
    simple.ColorBy(display, ("POINTS", "rho"))
    colours = simple.GetColorTransferFunction("rho")
    colours.ApplyPreset("Cool to Warm", True)
    display.RescaleTransferFunctionToDataRange(False, True)
    bar = simple.GetScalarBar(colours, view)
    bar.Title, bar.ComponentTitle = "rho", ""
    bar.TitleColor = bar.LabelColor = [0.0, 0.0, 0.0]
    bar.WindowLocation = "Any Location"
    bar.Orientation = "Vertical"
    bar.Position = [0.9, 0.15]
    bar.ScalarBarLength = 0.7
    display.SetScalarBarVisibility(view, True)
    label = simple.Text(Text=f"{title}, t = {time:.3g}: density")
    label_display = simple.Show(label, view)
    label_display.Color = [0.0, 0.0, 0.0]
    label_display.WindowLocation = "Upper Left Corner"
    # Parallel view down z of the x-y plane; the particles span 80% of the width from the left edge,
    # so that the colour bar on the right covers none of them.
    xmin, xmax, ymin, ymax, _, _ = reader.GetDataInformation().GetBounds()
    half_height = max((xmax - xmin) / 0.8 * height / (2 * width), 0.6 * (ymax - ymin))
    visible_width = 2 * half_height * width / height
    centre = [xmin - 0.025 * visible_width + visible_width / 2, (ymin + ymax) / 2, 0.0]
    view.CameraParallelProjection = 1
    view.CameraParallelScale = half_height
    view.CameraFocalPoint = centre
    view.CameraPosition = [centre[0], centre[1], 10.0 * visible_width]
    view.CameraViewUp = [0.0, 1.0, 0.0]
    simple.SaveScreenshot(path, view, ImageResolution=[width, height])
    return width, height


@contextlib.contextmanager
def x_display(xvfb, log_path):
    """$DISPLAY, or with `xvfb` a private Xvfb on a free display that it reports once it accepts
    clients (-displayfd), stopped on exit and killed with this process if that dies first. The
    server must not reset when its last client leaves: other programs probe X displays (Open MPI's
    hwloc looks for GPUs on :0, :1, ...), and a server resetting refuses clients for a moment."""
    if not xvfb:
        yield os.environ["DISPLAY"]
        return
    read_end, write_end = os.pipe()
    prctl = ctypes.CDLL(None).prctl  # looked up before the fork: the child only calls it
    die_with_parent = lambda: prctl(1, signal.SIGKILL)  # noqa: E731 (1: PR_SET_PDEATHSIG)
    command = [xvfb, "-displayfd", str(write_end), "-screen", "0", "1280x1024x24", "-nolisten", "tcp", "-noreset"]
    with open(log_path, "w") as log:
        server = subprocess.Popen(command, pass_fds=(write_end,), stdin=subprocess.DEVNULL, stdout=log,
                                  stderr=log, preexec_fn=die_with_parent)
    os.close(write_end)
    with os.fdopen(read_end) as reported:
        number = reported.readline().strip()
    try:
        if not number:
            with open(log_path) as log:
                sys.exit(f"{PROGRAM}: {xvfb} did not start:\n{log.read()}")
        os.environ["DISPLAY"] = f":{number}"
        yield os.environ["DISPLAY"]
    finally:
        server.terminate()
        server.wait(timeout=60)


def check_screenshot(path, width, height):
    """A PNG of the right size with particles drawn: the dense (warm) gas left of the thin (cool)."""
    if not require(os.path.isfile(path) and os.path.getsize(path) > 0, f"no screenshot {path}"):
        return
    png = vtkPNGReader()
    png.SetFileName(path)
    png.Update()
    image = png.GetOutput()
    size = image.GetDimensions()[:2]
    if not require(size == (width, height), f"{path} is {size[0]}x{size[1]}, not {width}x{height}"):
        return
    pixels = vtk_to_numpy(image.GetPointData().GetScalars()).reshape(height, width, -1)[:, :, :3].astype(int)
    drawn = np.any(pixels != 255, axis=2)
    # The data area only: the colour bar on the right has both ends of the colour map.
    data_area = pixels[:, : int(0.85 * width)]
    red, blue = data_area[:, :, 0], data_area[:, :, 2]
    warm_columns = np.nonzero(red - blue > 80)[1]
    cool_columns = np.nonzero(blue - red > 80)[1]
    print(f"{PROGRAM}: screenshot {path}: {width}x{height}, {drawn.mean():.1%} of the pixels drawn, "
          f"{len(warm_columns)} warm and {len(cool_columns)} cool pixels in the data area")
    require(drawn.mean() > 0.005, f"{path} is almost blank ({drawn.mean():.2%} of the pixels drawn)")
    if require(len(warm_columns) > 50 and len(cool_columns) > 50, f"{path} lacks high or low densities"):
        require(warm_columns.mean() < cool_columns.mean(),
                f"{path}: the dense (warm) gas is not on the left of the tube")


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("file")
    parser.add_argument("--screenshot", required=True, help="PNG to write")
    parser.add_argument("--title", default="Sod shock tube")
    parser.add_argument("--xvfb", help="the Xvfb program to render on (default: Xvfb when $DISPLAY is unset)")
    args = parser.parse_args()
    xvfb = args.xvfb or (None if os.environ.get("DISPLAY") else shutil.which("Xvfb"))
    if not xvfb and not os.environ.get("DISPLAY"):
        sys.exit(f"{PROGRAM}: no X display to render on: set DISPLAY or install Xvfb (Debian: xvfb)")

    steps = h5part_plot.step_indices(args.file, PROGRAM)
    file_steps = [h5part_plot.read_step(args.file, k, PROGRAM)[:2] for k in steps]
    times = [time for time, _ in file_steps]
    reader = simple.H5PartReader(FileName=args.file)
    require(list(reader.TimestepValues) == times,
            f"ParaView's TimestepValues {list(reader.TimestepValues)} are not the steps' TimeValue {times}")
    for step, (time, data) in zip(steps, file_steps):
        seen = check_step(reader, step, time, data)
        if seen:
            print(f"{PROGRAM}: Step#{step} at t = {time!r}: {seen[0]} points, point arrays {' '.join(sorted(seen[1]))}")
    if failures:
        sys.exit(f"{PROGRAM}: ParaView does not read {args.file} as written ({len(failures)} failures)")
    print(f"{PROGRAM}: ParaView's H5PartReader reads {args.file} as written: {len(steps)} steps, "
          f"TimestepValues {list(reader.TimestepValues)}")

    with x_display(xvfb, os.path.splitext(args.screenshot)[0] + ".xvfb.log"):
        size = screenshot(reader, times[-1], args.screenshot, args.title)
    check_screenshot(args.screenshot, *size)
    if failures:
        sys.exit(1)


if __name__ == "__main__":
    main()
