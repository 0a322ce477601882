// Writes the SPH particles as one H5Part step (the layout ParaView's H5PartReader and the plot
// scripts read): x y z, vx vy vz (zero beyond D), m rho P u h id, kind (0 fluid, 1 wall), cs, du_dt.
#pragma once

#include "specialization/sph/simulation.hh"

#include "flecsi_lite/execution.hh"
#include "flecsi_lite/io.hh"

#include <cstdint>
#include <string>
#include <vector>

namespace flecsph::sph {

/// Collective: writes every owned particle's quantities into the open step of `out`. After
/// distribute() the ranks' owned particles concatenated are in (key, id) order, so the file's
/// particle order does not depend on the rank count.
template<int D>
void write_particle_arrays(flecsi_lite::io::h5part_writer& out, simulation<D>& s) {
  using f = fields<D>;
  auto& p = *s.particles;
  const std::size_t n = p.owned_size();
  std::vector<double> buffer(n);
  const auto components = [&](const auto& reference, const char* const names[3]) {
    const auto view = flecsi_lite::host_view(reference);
    for (int k = 0; k < 3; ++k) {
      for (std::size_t i = 0; i < n; ++i) buffer[i] = k < D ? view(i)[k] : 0.0;
      out.write(names[k], buffer.data(), n);
    }
  };
  const auto scalar = [&](const char* name, const auto& reference) {
    const auto view = flecsi_lite::host_view(reference);
    out.write(name, view.data(), n);
  };
  static const char* const positions[3] = {"x", "y", "z"};
  static const char* const velocities[3] = {"vx", "vy", "vz"};
  components(f::position()(p), positions);
  components(f::velocity(p), velocities);
  scalar("m", f::mass()(p));
  scalar("rho", f::density(p));
  scalar("P", f::pressure(p));
  scalar("u", f::internal_energy(p));
  scalar("h", f::smoothing_length()(p));
  scalar("id", f::id()(p));
  scalar("cs", f::sound_speed(p));
  scalar("du_dt", f::internal_energy_rate(p));
  {
    const auto kind = flecsi_lite::host_view(f::kind(p));
    std::vector<std::int32_t> values(n);
    for (std::size_t i = 0; i < n; ++i) values[i] = static_cast<std::int32_t>(kind(i));
    out.write("kind", values.data(), n);
  }
}

/// Collective: one step at s.time (TimeValue, time, step, dt) with every owned particle.
template<int D>
void write_particles(flecsi_lite::io::h5part_writer& out, simulation<D>& s) {
  out.begin_step({s.time, s.step, s.dt});
  write_particle_arrays(out, s);
  out.end_step();
}

} // namespace flecsph::sph
