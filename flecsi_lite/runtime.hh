// The runtime: MPI and Kokkos start-up, options, parameter files, logging, timers.
#pragma once
#include "flecsi_lite/runtime/context.hh"
#include "flecsi_lite/runtime/log.hh"
#include "flecsi_lite/runtime/options.hh"
#include "flecsi_lite/runtime/parameters.hh"
#include "flecsi_lite/runtime/runtime.hh"
#include "flecsi_lite/runtime/timers.hh"
