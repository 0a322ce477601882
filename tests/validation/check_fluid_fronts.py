"""The surge front of one fluid dam-break run against another's (the 3D run periodic along the
span against the 2D run at the same dx and h): exit 1 unless max |Z_a - Z_b| / Z_b over
1 <= T <= 2.8 is at most BOUND. Reads the runs' .series.txt (apps/fluid/fluid.cc: the header
gives L, dx and g; the columns t and the largest fluid x, the front being that plus dx/2).

    check_fluid_fronts.py A.series.txt B.series.txt BOUND
"""
import re
import sys

import numpy as np


def front(path):
    with open(path) as f:
        header = f.readline()
    found = {k: float(re.search(k + r" = ([0-9.eE+-]+)", header).group(1)) for k in ("L", "dx", "g")}
    s = np.loadtxt(path)
    L = found["L"]
    return s[:, 0] * np.sqrt(2 * found["g"] / L), (s[:, 1] + 0.5 * found["dx"]) / L


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
