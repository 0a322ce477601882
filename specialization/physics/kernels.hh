// Smoothing kernels chosen at run time by name ("cubic_spline", "wendland_c2/c4/c6") and
// dispatched once per task to a template, so the per-pair kernel calls inline in hot loops.
#pragma once

#include "specialization/physics/kernels/cubic_spline.hh"
#include "specialization/physics/kernels/wendland.hh"

#include "flecsi_lite/runtime.hh"

#include <array>
#include <string_view>

namespace flecsph::physics {

enum class kernel_type { cubic_spline, wendland_c2, wendland_c4, wendland_c6 };

inline constexpr std::array<kernel_type, 4> all_kernel_types = {kernel_type::cubic_spline, kernel_type::wendland_c2,
                                                                kernel_type::wendland_c4, kernel_type::wendland_c6};

/// The parameter-file names of the kernels (the shapes' own names), the one table of the "kernel"
/// key's choices, its help and its errors.
const flecsi_lite::runtime::name_table<kernel_type>& kernel_names();

/// kernel_names().name(type).
std::string_view kernel_name(kernel_type type);
/// kernel_names().value(name): throws std::invalid_argument naming the valid kernels (and the
/// nearest one) when `name` is unknown.
kernel_type kernel_from_name(std::string_view name);

/// Calls `function(kernel)` with the empty kernel tag type of `type` in dimension D, e.g.
///   dispatch_kernel<3>(type, [&](auto kernel) { ... kernel.value(r, h) ... });
/// Every instantiation must return the same type.
template<int D, class Function>
decltype(auto) dispatch_kernel(kernel_type type, Function&& function) {
  switch (type) {
    case kernel_type::wendland_c2:
      return function(wendland_c2<D>{});
    case kernel_type::wendland_c4:
      return function(wendland_c4<D>{});
    case kernel_type::wendland_c6:
      return function(wendland_c6<D>{});
    case kernel_type::cubic_spline:
      break;
  }
  return function(cubic_spline<D>{});
}

}  // namespace flecsph::physics
