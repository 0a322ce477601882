// The execution model: execute<task>, reduce<task, op>, futures, forall.
#pragma once
#include "flecsi_lite/execution/execute.hh"
#include "flecsi_lite/execution/forall.hh"
