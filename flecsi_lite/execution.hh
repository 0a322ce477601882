// The execution model: execute<task>, reduce<task, op>, reduce_ghosts<op>, futures, reduction
// operations, forall.
#pragma once
#include "flecsi_lite/execution/execute.hh"
#include "flecsi_lite/execution/forall.hh"
#include "flecsi_lite/execution/future.hh"
#include "flecsi_lite/execution/reduce_ghosts.hh"
#include "flecsi_lite/execution/reduction.hh"
