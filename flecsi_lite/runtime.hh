// The runtime: MPI and Kokkos start-up, options, parameter files (keys declared once per settings
// struct, choice keys from name tables), logging, timers.
#pragma once
#include "flecsi_lite/runtime/context.hh"
#include "flecsi_lite/runtime/derived_values.hh"
#include "flecsi_lite/runtime/job_memory.hh"
#include "flecsi_lite/runtime/log.hh"
#include "flecsi_lite/runtime/name_table.hh"
#include "flecsi_lite/runtime/options.hh"
#include "flecsi_lite/runtime/parameter_block.hh"
#include "flecsi_lite/runtime/parameter_text.hh"
#include "flecsi_lite/runtime/parameters.hh"
#include "flecsi_lite/runtime/runtime.hh"
#include "flecsi_lite/runtime/thread_share.hh"
#include "flecsi_lite/runtime/timers.hh"
