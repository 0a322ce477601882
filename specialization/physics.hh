// The SPH physics an app may use directly: kernels, equations of state (ideal gas, polytropic,
// isothermal, Tait), artificial viscosity and conductivity, the smoothing length, softened
// gravity, the gravitational-wave quadrupole formula and the radiation reaction of a binary
// (specialization/physics/).
#pragma once

#include "specialization/physics/eos.hh"
#include "specialization/physics/gravitational_waves.hh"
#include "specialization/physics/gravity_softening.hh"
#include "specialization/physics/kernels.hh"
#include "specialization/physics/pressure_energy.hh"
#include "specialization/physics/radiation_reaction.hh"
#include "specialization/physics/smoothing_length.hh"
#include "specialization/physics/tait.hh"
#include "specialization/physics/time_step.hh"
#include "specialization/physics/viscosity.hh"
