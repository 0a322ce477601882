"""The Rayleigh-Taylor run's mode amplitude (apps/rayleigh_taylor/rt_profile.py: the Fourier
amplitude of v_y at the seeded k, weighted towards the interface) at every output step, and its
growth rate over the steps in WINDOW (--fit two_modes: the sigma of the best a exp(sigma t) + b
exp(-sigma t), the linear solution of a seed mixing the growing and the decaying mode; slope: the
slope of ln A, biased low while the decaying mode lasts) against the linear theory of the run's
set-up (rt_linear_theory.py, computed from the file's parameters: the smooth profile's
compressible rate unless --reference says otherwise): exit 1 when the relative difference exceeds
BOUND ('none': no bound), or the last step's amplitude lies outside --final LOW,HIGH, or (a run
with perturbation = 0) the fluid's largest rms speed over the steps exceeds --at-rest BOUND.

    check_rayleigh_taylor.py rt.h5part BOUND [--window 0.8,2.0] [--fit two_modes|slope]
                             [--reference smooth_compressible]
                             [--final LOW,HIGH] [--at-rest BOUND] [--json FILE]
"""
import argparse
import json
import os
import sys

import numpy as np

HERE = os.path.dirname(os.path.abspath(__file__))
sys.path.insert(0, os.path.join(HERE, "..", "..", "apps", "rayleigh_taylor"))
sys.path.insert(0, os.path.join(HERE, "..", "..", "apps", "plotting"))
import h5part_plot  # noqa: E402
import rt_linear_theory  # noqa: E402
import rt_profile  # noqa: E402

PROGRAM = "check_rayleigh_taylor"
REFERENCES = ("smooth_compressible", "smooth_incompressible", "sharp_incompressible")


def pair(text):
    low, high = (float(v) for v in text.split(","))
    return low, high


def rms_speeds(path, steps):
    """The rms speed of the fluid particles at each step."""
    speeds = []
    for step in steps:
        _, data, _ = h5part_plot.read_step(path, step, PROGRAM)
        fluid = data["kind"] == 0
        speeds.append(float(np.sqrt(np.mean(data["vx"][fluid] ** 2 + data["vy"][fluid] ** 2))))
    return np.array(speeds)


def main():
    parser = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    parser.add_argument("file")
    parser.add_argument("bound")
    parser.add_argument("--window", type=pair, default=(0.8, 2.0))
    parser.add_argument("--fit", choices=("two_modes", "slope"), default="two_modes")
    parser.add_argument("--reference", choices=REFERENCES, default="smooth_compressible")
    parser.add_argument("--final", type=pair)
    parser.add_argument("--at-rest", type=float)
    parser.add_argument("--json")
    arguments = parser.parse_args()
    if not os.path.isfile(arguments.file):
        print("%s: '%s' does not exist (the run did not write it)" % (PROGRAM, arguments.file), file=sys.stderr)
        sys.exit(3)
    setup = rt_profile.SetUp(h5part_plot.attributes(arguments.file, PROGRAM))
    steps = h5part_plot.step_indices(arguments.file, PROGRAM)

    def read(path, step):
        return h5part_plot.read_step(path, step, PROGRAM)

    times, amplitudes = rt_profile.amplitude_series(arguments.file, read, steps, setup)
    result = {"times": times.tolist(), "amplitudes": amplitudes.tolist(), "pass": True}
    if arguments.at_rest is not None:
        speeds = rms_speeds(arguments.file, steps)
        result.update(rms_speeds=speeds.tolist(), largest_rms_speed=float(speeds.max()), at_rest_bound=arguments.at_rest)
        result["pass"] = bool(speeds.max() <= arguments.at_rest)
        print("Rayleigh-Taylor at rest: largest rms speed of the fluid %.3e at t = %.3g (bound %g); mode amplitude "
              "at the end %.3e" % (speeds.max(), times[np.argmax(speeds)], arguments.at_rest, amplitudes[-1]))
    if arguments.final:
        inside = bool(arguments.final[0] <= amplitudes[-1] <= arguments.final[1])
        result.update(final_amplitude=float(amplitudes[-1]), final_range=list(arguments.final))
        result["pass"] = result["pass"] and inside
        print("Rayleigh-Taylor: mode amplitude %.5f at t = %.4g (range %g-%g)" %
              (amplitudes[-1], times[-1], arguments.final[0], arguments.final[1]))
    if arguments.bound != "none" or (arguments.final is None and arguments.at_rest is None):
        theory = rt_linear_theory.rates(setup)
        slope = rt_profile.growth_rate(times, amplitudes, arguments.window)
        two_modes = rt_profile.growth_rate_two_modes(times, amplitudes, arguments.window)
        rate = two_modes if arguments.fit == "two_modes" else slope
        difference = rate / theory[arguments.reference] - 1
        passed = arguments.bound == "none" or abs(difference) <= float(arguments.bound)
        for t, a in zip(times, amplitudes):
            print("  t = %.4f  A = %.6e" % (t, a))
        print("Rayleigh-Taylor: growth rate of A over t in [%g, %g]: %.4f (%s; two-mode fit %.4f, slope of ln A "
              "%.4f); linear theory %.4f (%s; smooth incompressible %.4f, sharp %.4f), relative difference %+.3f "
              "(bound %s); last A %.5f at t = %.4g" %
              (arguments.window[0], arguments.window[1], rate, arguments.fit, two_modes, slope,
               theory[arguments.reference], arguments.reference,
               theory["smooth_incompressible"], theory["sharp_incompressible"], difference, arguments.bound,
               amplitudes[-1], times[-1]))
        result.update(growth_rate=rate, fit=arguments.fit, two_mode_fit=two_modes, slope_of_ln_amplitude=slope,
                      theory=theory, reference=arguments.reference, relative_difference=difference,
                      window=list(arguments.window), bound=arguments.bound)
        result["pass"] = bool(result["pass"] and passed)
    print("%s: %s" % (PROGRAM, "pass" if result["pass"] else "FAIL"))
    if arguments.json:
        with open(arguments.json, "w") as out:
            json.dump(result, out, indent=1)
    sys.exit(0 if result["pass"] else 1)


if __name__ == "__main__":
    main()
