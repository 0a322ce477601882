"""The surge front of one fluid dam-break run against another's (the 3D run periodic along the
span against the 2D run at the same dx and h): exit 1 unless max |Z_a - Z_b| / Z_b over
1 <= T <= 2.8 is at most BOUND. Reads the runs' .series.txt (apps/fluid/front_errors.py).

    check_fluid_fronts.py A.series.txt B.series.txt BOUND
"""
import os
import sys

import numpy as np

sys.path.insert(0, os.path.join(os.path.dirname(os.path.abspath(__file__)), "..", "..", "apps", "fluid"))
from front_errors import front  # noqa: E402  (T and Z / L of a run's series)


def main():
    if len(sys.argv) != 4:
        sys.exit(__doc__)
    Ta, Za = front(sys.argv[1])
    Tb, Zb = front(sys.argv[2])
    bound = float(sys.argv[3])
    T = np.linspace(1, 2.8, 91)
    a, b = np.interp(T, Ta, Za), np.interp(T, Tb, Zb)
    if Ta[-1] < 2.8 or Tb[-1] < 2.8:
        sys.exit("check_fluid_fronts: a run ends before T = 2.8 (%g, %g)" % (Ta[-1], Tb[-1]))
    difference = np.abs(a - b) / b
    worst = int(np.argmax(difference))
    print("front of %s against %s over 1 <= T <= 2.8: max relative difference %.3e at T = %.2f "
          "(Z/L %.4f against %.4f), mean %.3e; bound %g" % (sys.argv[1], sys.argv[2], difference[worst], T[worst],
                                                           a[worst], b[worst], difference.mean(), bound))
    sys.exit(0 if difference[worst] <= bound else 1)


if __name__ == "__main__":
    main()
