// The weakly compressible liquids on the SPH step (specialization/fluid/): their settings, fields,
// forces, solid walls and the control model whose force evaluation they replace by name.
#pragma once

#include "specialization/fluid/fluid_model.hh"
#include "specialization/fluid/fluid_settings.hh"
