// The SPH driver, the header apps include: the task vocabulary (tasks.hh), the physics steps
// (steps.hh), the diagnostics (diagnostics.hh) and the standard control model of seed
// Algorithm 3 with its named actions (sph_model.hh), the self-gravity action that place_gravity
// adds to it (gravity.hh), plus initial_fields.hh to fill the particles an app creates.
#pragma once

#include "specialization/sph/model/simulation.hh"
#include "specialization/sph/model/tasks.hh"
#include "specialization/sph/step/diagnostics.hh"
#include "specialization/sph/step/gravity.hh"
#include "specialization/sph/step/initial_fields.hh"
#include "specialization/sph/step/sph_model.hh"
#include "specialization/sph/step/steps.hh"
