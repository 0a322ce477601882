"""The Kelvin-Helmholtz run's mode amplitude (McNally, Lyra & Passy 2012, eqs. 4-7;
apps/kelvin_helmholtz/kh_profile.py) at every output step, and its growth rate (the slope of ln M
over the steps in WINDOW) against the linear-theory rate of the profile (2.8193,
kh_linear_theory.py): exit 1 when the relative difference exceeds BOUND ('none': no bound) or the
last step's amplitude lies outside --final LOW,HIGH.

    check_kelvin_helmholtz.py kh.h5part BOUND [--window 0.5,1.5] [--final LOW,HIGH] [--json FILE]
"""
import argparse
import json
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "apps", "kelvin_helmholtz"))
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "apps", "plotting"))
import h5part_plot  # noqa: E402
import kh_profile  # noqa: E402

PROGRAM = "check_kelvin_helmholtz"


def pair(text):
    low, high = (float(v) for v in text.split(","))
    return low, high


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("file")
    parser.add_argument("bound")
    parser.add_argument("--window", type=pair, default=(0.5, 1.5))
    parser.add_argument("--final", type=pair)
    parser.add_argument("--reference", type=float, default=kh_profile.LINEAR_GROWTH_RATE)
    parser.add_argument("--json")
    arguments = parser.parse_args()
    if not os.path.isfile(arguments.file):
        print("%s: '%s' does not exist (the run did not write it)" % (PROGRAM, arguments.file), file=sys.stderr)
        sys.exit(3)

    def read(path, step):
        return h5part_plot.read_step(path, step, PROGRAM)

    times, amplitudes = kh_profile.amplitude_series(arguments.file, read, h5part_plot.step_indices(arguments.file,
                                                                                                  PROGRAM))
    rate = kh_profile.growth_rate(times, amplitudes, arguments.window)
    difference = rate / arguments.reference - 1
    passed = True
    if arguments.bound != "none":
        passed = abs(difference) <= float(arguments.bound)
    if arguments.final:
        passed = passed and arguments.final[0] <= amplitudes[-1] <= arguments.final[1]
    for t, m in zip(times, amplitudes):
        print("  t = %.4f  M = %.6f" % (t, m))
    print("Kelvin-Helmholtz: growth rate of M over t in [%g, %g]: %.4f, linear theory %.4f, relative difference "
          "%+.3f (bound %s); last M %.5f at t = %.4g%s: %s" %
          (arguments.window[0], arguments.window[1], rate, arguments.reference, difference, arguments.bound,
           amplitudes[-1], times[-1], " (range %g-%g)" % arguments.final if arguments.final else "",
           "pass" if passed else "FAIL"))
    if arguments.json:
        with open(arguments.json, "w") as out:
            json.dump({"times": times.tolist(), "amplitudes": amplitudes.tolist(), "growth_rate": rate,
                       "reference": arguments.reference, "relative_difference": difference,
                       "window": list(arguments.window), "bound": arguments.bound, "pass": bool(passed)}, out, indent=1)
    sys.exit(0 if passed else 1)


if __name__ == "__main__":
    main()
