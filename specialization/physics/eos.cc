// The name table of the equations of state (eos.hh) for parameter files.
#include "specialization/physics/eos.hh"

namespace flecsph::physics {

const flecsi_lite::runtime::name_table<eos_type>& eos_names() {
  static const flecsi_lite::runtime::name_table<eos_type> table{
    "equation of state",
    {{"ideal_gas", eos_type::ideal_gas}, {"polytropic", eos_type::polytropic}, {"isothermal", eos_type::isothermal}}};
  return table;
}

std::string_view eos_name(eos_type type) { return eos_names().name(type); }

eos_type eos_from_name(std::string_view name) { return eos_names().value(name); }

}  // namespace flecsph::physics
