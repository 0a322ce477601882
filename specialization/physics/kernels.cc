// Kernel names for parameter files, with "did you mean" errors for misspelled names.
#include "specialization/physics/kernels.hh"

#include "flecsi_lite/util.hh"

#include <stdexcept>
#include <string>
#include <vector>

namespace flecsph::physics {

std::string_view kernel_name(kernel_type type) {
  switch (type) {
  case kernel_type::cubic_spline: return cubic_spline_shape::name;
  case kernel_type::wendland_c2: return wendland_c2_shape::name;
  case kernel_type::wendland_c4: return wendland_c4_shape::name;
  case kernel_type::wendland_c6: return wendland_c6_shape::name;
  }
  throw std::invalid_argument("invalid kernel_type value");
}

kernel_type kernel_from_name(std::string_view name) {
  std::vector<std::string> names;
  for (kernel_type type : all_kernel_types) {
    if (kernel_name(type) == name) return type;
    names.emplace_back(kernel_name(type));
  }
  std::string message = "unknown kernel '" + std::string(name) + "'";
  if (auto nearest = flecsi_lite::util::nearest_name(name, names); !nearest.empty())
    message += "; did you mean '" + nearest + "'?";
  message += " (valid kernels:";
  for (const auto& valid : names) message += " " + valid;
  throw std::invalid_argument(message + ")");
}

} // namespace flecsph::physics
