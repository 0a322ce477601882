// The weakly compressible liquids on the SPH step (specialization/fluid/): their settings, fields,
// forces, solid walls and the control model whose force evaluation they replace by name; the
// gauges (pressure and velocity sensors) and the surge-front operator of the dam break.
#pragma once

#include "specialization/fluid/fluid_model.hh"
#include "specialization/fluid/fluid_settings.hh"
#include "specialization/fluid/gauge_file.hh"
#include "specialization/fluid/gauges.hh"
#include "specialization/fluid/surge_front.hh"
