"""Bounds on the dam break's surge front (apps/fluid/dam_break_fronts.py reads the gauge file's
front_x, the one front operator):

    check_dam_break_fronts.py reference RUN.gauges.csv MEAN ARRIVAL WIDTH
        against TrixiParticles' converged H/400 run, x_f / 2H over 1 <= t sqrt(g/H) <= 2.3: mean
        relative error at most MEAN, the wall arrival within ARRIVAL +- WIDTH.
    check_dam_break_fronts.py martin-moyce RUN.gauges.csv SHIFT_LOW SHIFT_HIGH MEAN RAW
        against Martin & Moyce (1952) Table 2 (nine points, 1 <= T <= 2.8): the run ahead of the
        experiment at every point by at most RAW (relative), its best constant delay in
        [SHIFT_LOW, SHIFT_HIGH], the mean error after that delay at most MEAN.
Exit 1 when a bound fails, 2 on bad usage.
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "apps", "fluid"))
import dam_break_fronts as fronts  # noqa: E402


def main():
    args = sys.argv[1:]
    failures = []
    if len(args) == 5 and args[0] == "reference":
        run = fronts.GaugeFile(args[1])
        bound, arrival, width = (float(v) for v in args[2:])
        mean, largest, mine, theirs = fronts.against_reference(run)
        print("front against TrixiParticles H/400 over 1 <= t sqrt(g/H) <= 2.3: mean relative error %.4f (bound %g), "
              "largest %.4f; wall arrival %.3f (bound %g +- %g; the reference's %.3f)" %
              (mean, bound, largest, mine, arrival, width, theirs))
        if not mean <= bound:
            failures.append("mean relative front error %.4f above %g" % (mean, bound))
        if not abs(mine - arrival) <= width:
            failures.append("wall arrival at t sqrt(g/H) = %.3f, not within %g +- %g" % (mine, arrival, width))
    elif len(args) == 6 and args[0] == "martin-moyce":
        run = fronts.GaugeFile(args[1])
        low, high, bound, raw_bound = (float(v) for v in args[2:])
        raw, shift, mean = fronts.against_martin_moyce(run)
        print("front against Martin & Moyce Table 2: raw errors %s (largest %.4f, bound %g, ahead at every point: %s); "
              "best delay %.3f (bound [%g, %g]), mean error after it %.4f (bound %g)" %
              (" ".join("%+.4f" % e for e in raw), np.max(np.abs(raw)), raw_bound, bool(np.all(raw > 0)), shift, low,
               high, mean, bound))
        if not np.all(raw > 0):
            failures.append("the run is not ahead of the experiment at every point")
        if not np.max(np.abs(raw)) <= raw_bound:
            failures.append("raw error %.4f above %g" % (np.max(np.abs(raw)), raw_bound))
        if not low <= shift <= high:
            failures.append("best delay %.3f outside [%g, %g]" % (shift, low, high))
        if not mean <= bound:
            failures.append("mean error after the delay %.4f above %g" % (mean, bound))
    else:
        sys.stderr.write(__doc__)
        sys.exit(2)
    for failure in failures:
        print("check_dam_break_fronts: FAILED: " + failure)
    sys.exit(1 if failures else 0)


if __name__ == "__main__":
    main()
