// Names of the equations of state for parameter files, with "did you mean" errors.
#include "specialization/physics/eos.hh"

#include "flecsi_lite/util.hh"

#include <array>
#include <stdexcept>
#include <string>

namespace flecsph::physics {

namespace {
constexpr std::array<eos_type, 3> all_eos_types = {eos_type::ideal_gas, eos_type::polytropic,
                                                   eos_type::isothermal};
}

std::string_view eos_name(eos_type type) {
  switch (type) {
  case eos_type::ideal_gas: return "ideal_gas";
  case eos_type::polytropic: return "polytropic";
  case eos_type::isothermal: return "isothermal";
  }
  throw std::invalid_argument("invalid eos_type value");
}

eos_type eos_from_name(std::string_view name) {
  std::array<std::string, all_eos_types.size()> names;
  for (std::size_t i = 0; i < all_eos_types.size(); ++i) {
    if (eos_name(all_eos_types[i]) == name) return all_eos_types[i];
    names[i] = std::string(eos_name(all_eos_types[i]));
  }
  std::string message = "unknown equation of state '" + std::string(name) + "'";
  if (auto nearest = flecsi_lite::util::nearest_name(name, names); !nearest.empty())
    message += "; did you mean '" + nearest + "'?";
  message += " (valid:";
  for (const auto& valid : names) message += " " + valid;
  throw std::invalid_argument(message + ")");
}

} // namespace flecsph::physics
