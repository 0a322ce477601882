// Fields of the heat-diffusion example: what an application author declares first.
#pragma once

#include "flecsi_lite/data.hh"
#include "flecsi_lite/topology/narray.hh"

namespace heat {
using mesh = flecsi_lite::topology::narray;
template<class T>
using field = flecsi_lite::field<T>;

inline const field<double>::definition<mesh> temperature{"temperature"};
inline const field<double>::definition<mesh> next_temperature{"next_temperature"};
}  // namespace heat
