// The runtime: MPI and Kokkos start-up, options, logging, timers.
#pragma once
#include "flecsi_lite/runtime/context.hh"
#include "flecsi_lite/runtime/log.hh"
#include "flecsi_lite/runtime/options.hh"
#include "flecsi_lite/runtime/runtime.hh"
#include "flecsi_lite/runtime/timers.hh"
