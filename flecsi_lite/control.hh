// The control model (control points, actions, dependencies, cycles).
#pragma once
#include "flecsi_lite/control/control_model.hh"
