// What a problem asks of the run's physics, checked in one place with one wording: an app
// states its need in one line, and a run that does not meet it stops with exit status 2 before
// anything is written ("sod: the exact solution needs eos = ideal_gas").
#pragma once

#include "specialization/physics/eos.hh"
#include "specialization/sph/model/settings.hh"

#include "flecsi_lite/runtime.hh"

#include <string>

namespace flecsph::sph {

/// Throws a parameter_error "<program>: <who> needs eos = <type>" unless the run's equation of
/// state is `type` (who: what needs it, e.g. "the exact solution").
inline void require_equation_of_state(const physics_settings& physics, physics::eos_type type,
                                      const std::string& program, const std::string& who) {
  if (physics.eos.type != type)
    throw flecsi_lite::runtime::parameter_error(program + ": " + who +
                                                " needs eos = " + std::string(physics::eos_name(type)));
}

}  // namespace flecsph::sph
