// The start-up banner's SPH line (app.hh): the particles as created and per rank, the kernel and
// the equation of state.
#pragma once

#include "specialization/physics/eos.hh"
#include "specialization/physics/kernels.hh"
#include "specialization/sph/model/fields.hh"
#include "specialization/sph/model/tasks.hh"
#include "specialization/sph/model/walls.hh"
#include "specialization/sph/run/app_state.hh"

#include "flecsi_lite/execution.hh"
#include "flecsi_lite/runtime.hh"

#include <cstddef>
#include <cstdint>

namespace flecsph::sph {
namespace detail {
inline std::uint64_t rank_value(std::uint64_t value) { return value; }

/// The banner's SPH line: the particles as created (a lattice may hold fewer than asked for),
/// per rank once distributed, the kernel and the equation of state.
template<int D>
void describe_particles(app_state<D>& s) {
  using flecsi_lite::reduce;
  namespace reduction = flecsi_lite::reduction;
  auto& p = *s.particles;
  const std::uint64_t owned = p.owned_size();
  const auto fewest = reduce<rank_value, reduction::min>(owned).get();
  const auto most = reduce<rank_value, reduction::max>(owned).get();
  const std::uint64_t walls = count_walls<D>(s);
  auto line = flecsi_lite::log::info();
  line << s.program << ": " << p.global_size() << " particles (" << p.global_size() - walls << " fluid, " << walls
       << " walls), " << fewest << " to " << most << " per rank; kernel " << physics::kernel_name(s.physics.kernel)
       << ", eos ";
  if (!s.equation_of_state.empty())
    line << s.equation_of_state;
  else
    line << physics::eos_name(s.physics.eos.type);
  if (s.equation_of_state.empty() && s.physics.eos.type == physics::eos_type::ideal_gas)
    line << " (gamma " << s.physics.eos.ideal.gamma << ")";
}
}  // namespace detail
}  // namespace flecsph::sph
