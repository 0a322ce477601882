// Reading and checking a cached glass, and the keys of a glass start (glass_tiling.hh).
#include "glass_tiling.hh"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <iomanip>
#include <sstream>
#include <stdexcept>

namespace glass {

std::string cache_name(int dimension, std::int64_t per_side, const std::string& kernel, double eta) {
  std::ostringstream name;
  name << std::setprecision(6) << "glass_" << dimension << "d_" << per_side << "_" << kernel << "_eta" << eta
       << ".h5part";
  return name.str();
}

flecsi_lite::io::run_state glass_attributes(std::int64_t per_side, const sph::physics_settings& physics) {
  return {{"glass_particles_per_side", per_side},
          {"glass_kernel", std::string(flecsph::physics::kernel_name(physics.kernel))},
          {"glass_eta", physics.eta}};
}

const flecsi_lite::runtime::name_table<start_layout>& layout_names() {
  static const flecsi_lite::runtime::name_table<start_layout> names{
    "initial lattice", {{"lattice", start_layout::lattice}, {"glass", start_layout::glass}}};
  return names;
}

namespace {
flecsi_lite::runtime::parameter_block<layout_settings> declare_layout() {
  flecsi_lite::runtime::parameter_block<layout_settings> keys;
  keys.choice("initial_lattice", &layout_settings::layout, layout_names(),
              "lattice (cubic, cell centres) or glass (a cached glass of the glass app, tiled)");
  keys.string("glass_file", &layout_settings::glass_file,
              "with initial_lattice = glass: the glass (auto: the glass app's cache name for glass_per_side, the "
              "kernel and eta)");
  keys
    .integer("glass_per_side", &layout_settings::glass_per_side,
             "with initial_lattice = glass: particles per side of the glass (a divisor of particles_per_side)")
    .at_least(4);
  return keys;
}

std::string describe(const flecsi_lite::io::attribute_value& value) {
  std::ostringstream text;
  std::visit([&](const auto& v) { text << v; }, value);
  return text.str();
}
}  // namespace

const flecsi_lite::runtime::parameter_block<layout_settings>& layout_parameters() {
  static const auto block = declare_layout();
  return block;
}

std::int64_t tiles_per_side(const layout_settings& settings, std::int64_t problem_per_side,
                            const std::string& program) {
  if (problem_per_side % settings.glass_per_side != 0)
    throw flecsi_lite::runtime::parameter_error(
      program + ": particles_per_side = " + std::to_string(problem_per_side) +
      " is not a multiple of glass_per_side = " + std::to_string(settings.glass_per_side) +
      " (initial_lattice = glass tiles the glass over the box)");
  return problem_per_side / settings.glass_per_side;
}

template<int D>
unit_glass<D> read_glass(const layout_settings& settings, const sph::physics_settings& physics) {
  const std::string kernel(flecsph::physics::kernel_name(physics.kernel));
  const std::string path =
    settings.glass_file == "auto" ? cache_name(D, settings.glass_per_side, kernel, physics.eta) : settings.glass_file;
  if (!std::filesystem::is_regular_file(path)) {
    std::ostringstream message;
    message << std::setprecision(17) << "the glass '" << path
            << "' (glass_file) does not exist; make it with\n  glass apps/glass/glass_" << D
            << "d.par --set dimension=" << D << " --set particles_per_side=" << settings.glass_per_side
            << " --set kernel=" << kernel << " --set eta=" << physics.eta << " --set output_file=" << path;
    throw std::runtime_error(message.str());
  }
  const flecsi_lite::io::h5part_reader in(path);
  const auto names = in.root_attribute_names();
  const auto expected = glass_attributes(settings.glass_per_side, physics);
  std::vector<std::pair<std::string, flecsi_lite::io::attribute_value>> wanted(expected.begin(), expected.end());
  wanted.emplace_back("dimension", std::int64_t{D});
  for (const auto& [name, value] : wanted) {
    if (std::find(names.begin(), names.end(), name) == names.end())
      throw std::runtime_error("'" + path + "' is not a glass of the glass app: it has no root attribute '" + name +
                               "'");
    const auto found = in.root_attribute(name);
    if (found != value)
      throw std::runtime_error("the glass '" + path + "' has " + name + " = " + describe(found) + ", the run needs " +
                               describe(value) + " (glass_per_side, dimension, kernel and eta must be the glass's)");
  }
  const auto step = in.last_step();
  std::uint64_t count = 1;
  for (int k = 0; k < D; ++k) count *= static_cast<std::uint64_t>(settings.glass_per_side);
  if (in.particle_count(step) != count)
    throw std::runtime_error("the glass '" + path + "' holds " + std::to_string(in.particle_count(step)) +
                             " particles, not glass_per_side^" + std::to_string(D) + " = " + std::to_string(count));
  unit_glass<D> glass;
  glass.per_side = settings.glass_per_side;
  glass.positions.resize(count);
  const char* axes[3] = {"x", "y", "z"};
  for (int k = 0; k < D; ++k) {
    const auto values = in.read<double>(step, axes[k], flecsi_lite::io::slice{0, count});
    for (std::uint64_t i = 0; i < count; ++i) {
      if (!std::isfinite(values[i]))
        throw std::runtime_error("the glass '" + path + "' has a position that is not finite");
      glass.positions[i][k] = values[i] - std::floor(values[i]);  // the periodic image in [0, 1)
    }
  }
  return glass;
}

template unit_glass<2> read_glass<2>(const layout_settings&, const sph::physics_settings&);
template unit_glass<3> read_glass<3>(const layout_settings&, const sph::physics_settings&);

}  // namespace glass
