"""Checks of the fluid app's gauge files (gauge_file; specialization/fluid/gauges.hh).

    check_gauges.py same A.csv B.csv [--restarted]
        A and B hold the same rows, bit for bit (rank invariance; a restart's continuation, which
        must moreover carry the line '# restarted at step N' with N > 0).
    check_gauges.py hydrostatic TANK.csv TOLERANCE
        the still tank (depth = the file's length H): every gauge's last pressure within
        TOLERANCE of rho0 g (H - y) at its face's mid-point (0 above the water), its speed below
        1e-3 sqrt(g H); and the front (front_x) at the far wall of the tank 2 H wide, within dx / 20 (the lattice settles).
Exit 1 when a check fails, 2 on bad usage.
"""
import math
import os
import re
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "apps", "fluid"))
from dam_break_fronts import GaugeFile  # noqa: E402


def rows(path):
    with open(path) as f:
        text = f.read().splitlines()
    return [line for line in text if not line.startswith("#")], [line for line in text if line.startswith("#")]


def same(a, b, restarted):
    rows_a, _ = rows(a)
    rows_b, header_b = rows(b)
    failures = []
    if len(rows_a) < 2:
        failures.append("%s has %d rows" % (a, len(rows_a)))
    if rows_a != rows_b:
        differing = next((i for i, (x, y) in enumerate(zip(rows_a, rows_b)) if x != y), min(len(rows_a), len(rows_b)))
        failures.append("the rows differ (%d and %d rows; first difference at row %d: '%s' against '%s')" %
                        (len(rows_a), len(rows_b), differing + 1, rows_a[differing] if differing < len(rows_a) else "",
                         rows_b[differing] if differing < len(rows_b) else ""))
    if restarted:
        marks = [int(m.group(1)) for m in (re.match(r"# restarted at step (\d+)", h) for h in header_b) if m]
        if not marks or marks[-1] <= 0:
            failures.append("%s carries no '# restarted at step N' line with N > 0" % b)
        else:
            print("%s continues at step %d" % (b, marks[-1]))
    print("gauge rows of %s and %s: %d and %d rows, %s" % (a, b, len(rows_a), len(rows_b),
                                                           "identical" if rows_a == rows_b else "different"))
    return failures


def faces(path):
    out = []
    with open(path) as f:
        for line in f:
            found = re.match(r"# gauge (\d+): (\d+) samples from \(([^,]+), ([^)]+)\) to \(([^,]+), ([^)]+)\)", line)
            if found:
                x1, y1, x2, y2 = (float(v) for v in found.groups()[2:])
                out.append(((x1 + x2) / 2, (y1 + y2) / 2))
    return out


def hydrostatic(path, tolerance):
    run = GaugeFile(path)
    H = run.length
    scale = run.rho0 * run.g * H
    failures = []
    positions = faces(path)
    if not positions:
        failures.append("%s has no gauges" % path)
    for k, (x, y) in enumerate(positions, start=1):
        p = run["p_%d" % k][-1]
        speed = math.hypot(run["vx_%d" % k][-1], run["vy_%d" % k][-1])
        expected = max(run.rho0 * run.g * (H - y), 0.0)
        error = abs(p - expected) / scale
        print("gauge %d at (%.4g, %.4g): p = %.6g Pa, rho0 g (H - y) = %.6g Pa, |difference| = %.2e rho0 g H; "
              "speed %.2e sqrt(g H)" % (k, x, y, p, expected, error, speed / math.sqrt(run.g * H)))
        if not error <= tolerance:
            failures.append("gauge %d: pressure off by %.3e rho0 g H (bound %g)" % (k, error, tolerance))
        if not speed <= 1e-3 * math.sqrt(run.g * H):
            failures.append("gauge %d: speed %.3e m/s" % (k, speed))
    front = run["front_x"][-1]
    print("front_x %.10g m against the far wall at %.10g m" % (front, 2 * H))
    if not abs(front - 2 * H) <= 0.05 * run.dx:
        failures.append("front_x %.10g m, not the far wall at %.10g m" % (front, 2 * H))
    return failures


def main():
    args = sys.argv[1:]
    if len(args) >= 3 and args[0] == "same":
        failures = same(args[1], args[2], "--restarted" in args[3:])
    elif len(args) == 3 and args[0] == "hydrostatic":
        failures = hydrostatic(args[1], float(args[2]))
    else:
        sys.stderr.write(__doc__)
        sys.exit(2)
    for failure in failures:
        print("check_gauges: FAILED: " + failure)
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
