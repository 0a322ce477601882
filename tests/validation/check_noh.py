"""The Noh implosion's last step against the exact solution (apps/noh/noh_analysis.py): exit 1
unless |shock radius error| <= SHOCK and |post-shock density error| <= DENSITY (the issue's
bounds: 0.05 and 0.10); prints the measures, the wall heating included.

    check_noh.py noh_2d.h5part SHOCK DENSITY
"""
import os
import sys

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import validation_arguments  # noqa: E402

validation_arguments.use_app_modules("noh")
import h5part_plot  # noqa: E402
import noh_analysis  # noqa: E402

PROGRAM = "check_noh"


def main():
    time, data, attributes, (shock_bound, density_bound) = validation_arguments.last_step(PROGRAM, __doc__, 2)
    number = h5part_plot.number
    dimension = int(number(attributes, "dimension", 2))
    gamma = number(attributes, "gamma", 5.0 / 3.0)
    rho0 = number(attributes, "rho0", 1.0)
    speed = number(attributes, "inflow_speed", 1.0)
    r, _ = noh_analysis.radii(data, dimension)
    m = noh_analysis.measure(r, data["rho"], data["u"], time, dimension, gamma, rho0, speed)
    print(noh_analysis.summary(m, dimension))
    ok = abs(m["shock_error"]) <= shock_bound and abs(m["density_error"]) <= density_bound
    print("check_noh: %s (bounds: shock radius %g, post-shock density %g)" % ("pass" if ok else "FAIL", shock_bound,
                                                                             density_bound))
    sys.exit(0 if ok else 1)


if __name__ == "__main__":
    main()
