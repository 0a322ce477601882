"""The command line that the validation checks of an app's last step share (check_noh.py,
check_gresho.py): an H5Part file written by the app, then the check's bounds. A wrong count of
arguments or a bound that is no number is a usage error (exit 2, with the check's usage); a file
that does not exist is a file error (exit 3), as the project's programs do.

    validation_arguments.use_app_modules("noh")         # apps/noh and apps/plotting importable
    time, data, attributes, (shock, density) = validation_arguments.last_step("check_noh", __doc__, 2)
"""
import os
import sys

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..")


def use_app_modules(app):
    """Puts apps/<app> (its analysis module) and apps/plotting (h5part_plot) on sys.path."""
    for folder in ("plotting", app):
        sys.path.insert(0, os.path.join(ROOT, "apps", folder))


def last_step(program, usage, bound_count):
    """(time, data, root attributes, bounds) of the last step of the file sys.argv[1], the bounds
    being the `bound_count` numbers that follow it."""
    if len(sys.argv) != 2 + bound_count:
        print(usage, file=sys.stderr)
        sys.exit(2)
    path = sys.argv[1]
    bounds = []
    for text in sys.argv[2:]:
        try:
            bounds.append(float(text))
        except ValueError:
            print(f"{program}: the bound '{text}' is not a number", file=sys.stderr)
            sys.exit(2)
    if not os.path.isfile(path):
        print(f"{program}: '{path}' does not exist (the run did not write it)", file=sys.stderr)
        sys.exit(3)
    import h5part_plot  # after use_app_modules

    time, data, attributes = h5part_plot.read_step(path, None, program)
    return time, data, attributes, bounds
