#!/usr/bin/python3
# The plot scripts report what the apps report (issue 13, item 14): runs sod (or sedov), then
# apps/sod/plot_sod.py (apps/sedov/plot_sedov.py) on the file it wrote, parses both reports and
# requires every number (Sod: the L1 errors of density, pressure, velocity and their particle
# count; Sedov: shock front, Sedov-Taylor radius, density peak radius and mean) to agree to 1e-10
# relative, and the PNG to be written.
#
#   plot_matches_app.py sod|sedov APP PARAMETER_FILE PLOT_SCRIPT EXACT_SOLUTION STEM \
#                       [--set key=value ...] -- LAUNCHER...
import os
import re
import subprocess
import sys

NUMBER = r"([-+0-9.eE]+)"
# Each app's report line and the plot script's, with the numbers in the same order.
REPORTS = {
    "sod": (r"sod: L1 errors at t = \S+ over (\d+) particles with .*: density %s, pressure %s, velocity %s"
            % (NUMBER, NUMBER, NUMBER),
            r"^Sod at t = \S+: L1 errors over (\d+) particles with .*: density %s, pressure %s, velocity %s"
            % (NUMBER, NUMBER, NUMBER),
            ("particles", "L1 density", "L1 pressure", "L1 velocity")),
    "sedov": (r"sedov: at t = \S+ the shock front \(half height\) is at r = %s, Sedov-Taylor shock radius %s, "
              r"relative difference \S+; the density peaks at r = %s \(mean %s;" % (NUMBER, NUMBER, NUMBER, NUMBER),
              r"^Sedov \dD at t = \S+: density peak at r = %s, Sedov-Taylor shock at r = %s, shock front "
              r"\(half height\) at r = %s, relative difference \S+; mean density at the peak %s"
              % (NUMBER, NUMBER, NUMBER, NUMBER),
              ("shock front", "Sedov-Taylor radius", "density peak radius", "density peak mean")),
}
# The plot line's numbers in the app line's order (Sedov prints them in another order).
PLOT_ORDER = {"sod": (0, 1, 2, 3), "sedov": (2, 1, 0, 3)}
RELATIVE = 1e-10


def run(command, what):
    result = subprocess.run(command, capture_output=True, text=True)
    sys.stdout.write(result.stdout + result.stderr)
    if result.returncode != 0:
        sys.exit("plot_matches_app: %s failed with exit %d: %s" % (what, result.returncode, " ".join(command)))
    return result.stdout + result.stderr


def numbers(pattern, text, what):
    match = re.search(pattern, text, re.MULTILINE)
    if not match:
        sys.exit("plot_matches_app: no report line of %s (pattern %s)" % (what, pattern))
    return [float(value) for value in match.groups()]


def main():
    kind, app, parameters, plot, exact, stem = sys.argv[1:7]
    rest = sys.argv[7:]
    split = rest.index("--")
    settings, launcher = rest[:split], rest[split + 1:]
    output, png = stem + ".h5part", stem + ".png"
    for path in (output, png):
        if os.path.exists(path):
            os.remove(path)
    app_text = run(launcher + [app, parameters, "--set", "output_file=" + output, "--set", "checkpoint_file=none",
                               "--no-timers"] + settings, kind)
    plot_text = run(["/usr/bin/python3", plot, output, "--output", png, "--exact", exact], os.path.basename(plot))
    app_pattern, plot_pattern, names = REPORTS[kind]
    app_values = numbers(app_pattern, app_text, kind)
    plotted = numbers(plot_pattern, plot_text, os.path.basename(plot))
    plot_values = [plotted[k] for k in PLOT_ORDER[kind]]
    failed = False
    for name, a, p in zip(names, app_values, plot_values):
        difference = abs(a - p) / max(abs(a), abs(p), 1e-300)
        ok = a != 0 and difference <= RELATIVE
        print("%-20s app %.12g  plot %.12g  relative difference %.2e %s" % (name, a, p, difference,
                                                                            "ok" if ok else "FAILS"))
        failed = failed or not ok
    with open(png, "rb") as image:
        header = image.read(8)
    if header != b"\x89PNG\r\n\x1a\n" or os.path.getsize(png) < 1000:
        sys.exit("plot_matches_app: %s is no PNG image" % png)
    print("%s: %d bytes of PNG" % (png, os.path.getsize(png)))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
