// The time of one H5Part step: simulation time, iteration number and time step.
#pragma once

#include <cstdint>

namespace flecsi_lite::io {

struct step_info {
  double time = 0;
  std::int64_t step = 0;  // the simulation's iteration number (not the index k of Step#k)
  double dt = 0;
};

}  // namespace flecsi_lite::io
