// The surge front of Martin & Moyce (1952), Phil. Trans. R. Soc. A 244, 312-324, Fig. 3 (column
// a = 2.25 in, n^2 = 2: height 2a), as digitized in PySPH's examples/db_exp_data.py; the same
// table is martin_moyce_1952.txt for the plot script.
#pragma once

#include <vector>

namespace fluid_app {

struct front_point {
  double T;  ///< t sqrt(2 g / a)
  double Z;  ///< front position / a
};

inline const std::vector<front_point>& martin_moyce_front() {
  static const std::vector<front_point> points = {{0.832, 1.217},  {1.219, 1.474},  {1.997, 2.292}, {2.547, 2.995},
                                                  {3.345, 4.134},  {4.034, 4.944},  {4.418, 5.881}, {5.091, 6.980},
                                                  {5.685, 7.945},  {6.306, 8.966},  {6.822, 9.986}, {7.439, 10.963},
                                                  {8.031, 11.977}, {8.633, 13.005}, {9.237, 13.970}};
  return points;
}

}  // namespace fluid_app
