"""The Gresho vortex's last step against the steady exact state (apps/gresho/gresho_analysis.py):
prints the binned L1 error of v_phi; exit 1 when it exceeds BOUND (the issue's bound at 64^2 and
t = 1: 0.04).

    check_gresho.py gresho.h5part BOUND
"""
import os
import sys

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "apps", "gresho"))
sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "apps", "plotting"))
import gresho_analysis  # noqa: E402
import h5part_plot  # noqa: E402

PROGRAM = "check_gresho"


def main():
    if len(sys.argv) != 3:
        sys.exit(__doc__)
    if not os.path.isfile(sys.argv[1]):
        print("%s: '%s' does not exist (the run did not write it)" % (PROGRAM, sys.argv[1]), file=sys.stderr)
        sys.exit(3)
    time, data, _ = h5part_plot.read_step(sys.argv[1], None, "check_gresho")
    r, v_phi = gresho_analysis.polar(data)
    error = gresho_analysis.l1_error(r, v_phi)
    bound = float(sys.argv[2])
    print("Gresho vortex at t = %.6g, %d particles: binned L1 error of v_phi %.5f (bound %g): %s" %
          (time, len(r), error, bound, "pass" if error <= bound else "FAIL"))
    sys.exit(0 if error <= bound else 1)


if __name__ == "__main__":
    main()
