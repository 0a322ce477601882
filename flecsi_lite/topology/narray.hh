// The narray topology (1-D partitioned index space with halos).
#pragma once
#include "flecsi_lite/topology/narray/narray.hh"
