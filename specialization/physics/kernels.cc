// The name table of the smoothing kernels (kernels.hh), from the names of the kernel shapes.
#include "specialization/physics/kernels.hh"

namespace flecsph::physics {

const flecsi_lite::runtime::name_table<kernel_type>& kernel_names() {
  static const flecsi_lite::runtime::name_table<kernel_type> table{
    "kernel",
    {{cubic_spline_shape::name, kernel_type::cubic_spline},
     {wendland_c2_shape::name, kernel_type::wendland_c2},
     {wendland_c4_shape::name, kernel_type::wendland_c4},
     {wendland_c6_shape::name, kernel_type::wendland_c6}}};
  return table;
}

std::string_view kernel_name(kernel_type type) { return kernel_names().name(type); }

kernel_type kernel_from_name(std::string_view name) { return kernel_names().value(name); }

}  // namespace flecsph::physics
