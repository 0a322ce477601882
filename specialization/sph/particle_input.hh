// Reads SPH particles from one step of an H5Part file in parallel (the seed's "read f in
// parallel"): rank r of p reads the r-th balanced block of the step's particles, then the driver
// distributes them. The layout is the one write_particles writes, so an output file (or a
// checkpoint) of any run is valid initial data, and so is a file a user makes with h5py:
//
//   required   x (and y in 2D, y z in 3D), m, h, u        (reals: float64 or float32)
//   optional   vx vy vz (0), rho (initial guess only), id (the particle's index in the step),
//              kind (0 fluid, 1 wall; default fluid)
//
// Impossible values (no particles, non-finite positions, m <= 0, h <= 0, u < 0, rho < 0, unknown
// kinds) are errors naming the file, the step, the dataset and the first bad particle, thrown on
// every rank alike.
#pragma once

#include "specialization/sph/driver.hh"

#include "flecsi_lite/io.hh"

#include <cmath>
#include <cstdint>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace flecsph::sph {

/// "'path' step 12" for messages: the simulation's iteration number of H5Part step `index`.
inline std::string describe_input_step(const flecsi_lite::io::h5part_reader& in, std::int64_t index) {
  return "'" + in.path() + "' Step#" + std::to_string(index);
}

/// This rank's block of dataset `name` as T, from any numeric element type of the file (users'
/// files may hold float32 positions or int32 ids).
template<class T>
std::vector<T> read_converted(const flecsi_lite::io::h5part_reader& in, std::int64_t step, const std::string& name) {
  using flecsi_lite::io::element_type;
  const auto convert = [](const auto& values) { return std::vector<T>(values.begin(), values.end()); };
  switch (in.dataset_type(step, name)) {
  case element_type::float64: return convert(in.read<double>(step, name));
  case element_type::float32: return convert(in.read<float>(step, name));
  case element_type::int64: return convert(in.read<std::int64_t>(step, name));
  case element_type::uint64: return convert(in.read<std::uint64_t>(step, name));
  case element_type::int32: return convert(in.read<std::int32_t>(step, name));
  default: break;
  }
  throw flecsi_lite::io::element_type_error(describe_input_step(in, step) + " dataset '" + name +
                                            "' is not numeric (float64, float32, int64, uint64 or int32)");
}

namespace detail {
/// Throws (on this rank) when some value of `values` breaks `valid`; `rule` says what is expected.
template<class Valid>
void check_values(const std::vector<double>& values, const std::string& where, const std::string& name,
                  std::uint64_t first_index, const char* rule, Valid valid) {
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (valid(values[i])) continue;
    std::ostringstream message;
    message << where << ": particle " << first_index + i << " has " << name << " = " << values[i] << " (" << rule
            << ")";
    throw std::invalid_argument(message.str());
  }
}
} // namespace detail

/// Collective: creates the particles of `s` from step `step` (the index k of Step#k; -1: the last)
/// of `in`, with this rank's block of them. The tree settings (box, periodic axes) must be set.
/// Returns the step index read.
template<int D>
std::int64_t read_particles(simulation<D>& s, const flecsi_lite::io::h5part_reader& in, std::int64_t step = -1) {
  if (step < 0) step = in.last_step();
  const std::string where = describe_input_step(in, step);
  const std::uint64_t total = in.particle_count(step);
  if (total == 0) throw std::invalid_argument(where + " holds no particles");
  static const char* const coordinates[3] = {"x", "y", "z"};
  static const char* const velocities[3] = {"vx", "vy", "vz"};
  std::vector<std::vector<double>> x(D), v(D);
  for (int k = 0; k < D; ++k) x[k] = read_converted<double>(in, step, coordinates[k]);
  for (int k = 0; k < D; ++k)
    if (in.has_dataset(step, velocities[k])) v[k] = read_converted<double>(in, step, velocities[k]);
  const auto m = read_converted<double>(in, step, "m");
  const auto h = read_converted<double>(in, step, "h");
  const auto u = read_converted<double>(in, step, "u");
  const bool has_rho = in.has_dataset(step, "rho"), has_id = in.has_dataset(step, "id");
  const bool has_kind = in.has_dataset(step, "kind");
  const auto rho = has_rho ? read_converted<double>(in, step, "rho") : std::vector<double>();
  const auto ids = has_id ? read_converted<std::uint64_t>(in, step, "id") : std::vector<std::uint64_t>();
  const auto kinds = has_kind ? read_converted<double>(in, step, "kind") : std::vector<double>();
  const flecsi_lite::io::slice block = in.block(step);

  flecsi_lite::io::agree(flecsi_lite::runtime::communicator(), [&] {
    const auto finite = [](double value) { return std::isfinite(value); };
    for (int k = 0; k < D; ++k)
      detail::check_values(x[k], where, coordinates[k], block.offset, "positions must be finite", finite);
    for (int k = 0; k < D; ++k)
      detail::check_values(v[k], where, velocities[k], block.offset, "velocities must be finite", finite);
    detail::check_values(m, where, "m", block.offset, "masses must be positive",
                         [](double value) { return value > 0 && std::isfinite(value); });
    detail::check_values(h, where, "h", block.offset, "smoothing lengths must be positive",
                         [](double value) { return value > 0 && std::isfinite(value); });
    detail::check_values(u, where, "u", block.offset, "internal energies must be >= 0",
                         [](double value) { return value >= 0 && std::isfinite(value); });
    detail::check_values(rho, where, "rho", block.offset, "densities must be >= 0",
                         [](double value) { return value >= 0 && std::isfinite(value); });
    detail::check_values(kinds, where, "kind", block.offset, "0 for fluid or 1 for wall particles",
                         [](double value) { return value == 0 || value == 1; });
  });

  create_particles(s, block.count);
  const initial_views<D> set(*s.particles);
  for (std::size_t i = 0; i < block.count; ++i) {
    for (int k = 0; k < D; ++k) {
      set.x(i)[k] = x[k][i];
      set.v(i)[k] = v[k].empty() ? 0.0 : v[k][i];
    }
    set.id(i) = has_id ? ids[i] : block.offset + i;
    set.m(i) = m[i];
    set.h(i) = h[i];
    set.kind(i) = has_kind && kinds[i] == 1 ? particle_kind::wall : particle_kind::fluid;
    set.rho(i) = has_rho ? rho[i] : 0.0;
    set.u(i) = u[i];
  }
  return step;
}

} // namespace flecsph::sph
