"""The Gresho vortex's last step against the steady exact state (apps/gresho/gresho_analysis.py):
prints the binned L1 error of v_phi; exit 1 when it exceeds BOUND (the issue's bound at 64^2 and
t = 1: 0.04).

    check_gresho.py gresho.h5part BOUND
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import validation_arguments  # noqa: E402

validation_arguments.use_app_modules("gresho")
import gresho_analysis  # noqa: E402

PROGRAM = "check_gresho"


def main():
    time, data, _, (bound,) = validation_arguments.last_step(PROGRAM, __doc__, 1)
    r, v_phi = gresho_analysis.polar(data)
    error = gresho_analysis.l1_error(r, v_phi)
    print("Gresho vortex at t = %.6g, %d particles: binned L1 error of v_phi %.5f (bound %g): %s" %
          (time, len(r), error, bound, "pass" if error <= bound else "FAIL"))
    sys.exit(0 if error <= bound else 1)


if __name__ == "__main__":
    main()
