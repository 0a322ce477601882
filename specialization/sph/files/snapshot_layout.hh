// What an SPH snapshot holds, in the layout of SWIFT (Schaller et al. 2024; SWIFT's src/common_io.c,
// parallel_io.c, units.c, hydro/*/hydro_io.h) that GADGET-2 readers also read: the datasets of each
// particle type, which are the fields whose definitions say so (model/fields.hh: in_snapshots,
// units), with the H5Part datasets they are made of, and the unit attributes SWIFT writes on every
// dataset and in the Units group.
//
// Smoothing lengths: SmoothingLengths holds our h, whose kernel support radius is H = 2 h for every
// kernel (physics::kernel_support; Monaghan's M4 convention, the one splash assumes). SWIFT's own
// h is H / kernel_gamma (Dehnen & Aly 2012: 1.825742 for the cubic spline in 3D), so a SWIFT h
// equals 2 / kernel_gamma of ours. The HydroScheme group states the ratio H / h.
#pragma once

#include "specialization/sph/files/particle_output.hh"
#include "specialization/sph/files/snapshot_settings.hh"
#include "specialization/sph/model/fields.hh"
#include "specialization/sph/model/simulation.hh"

#include "flecsi_lite/data.hh"
#include "flecsi_lite/io.hh"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <utility>
#include <vector>

namespace flecsph::sph {

/// The particle types of a snapshot: the fluid in PartType0 (GADGET's gas), the wall particles
/// in PartType2 (GADGET's first boundary type; splash calls it "boundary 1").
inline constexpr int fluid_part_type = 0, wall_part_type = 2, part_type_count = 6;

inline std::string part_type_group(int type) { return "PartType" + std::to_string(type); }

/// Powers of the base units (mass, length, time) of a quantity, declared on its field.
using unit_exponents = flecsi_lite::data::unit_exponents;

/// One snapshot dataset: its name, the H5Part datasets it is made of (1 column, or 3 for a
/// vector, zeros for an absent component), its units and SWIFT's "Description".
struct snapshot_quantity {
  std::string name;
  std::vector<std::string> sources;
  unit_exponents units;
  std::string description;
};

/// The datasets of a particle type of run `s`: every registered field that its definition puts in
/// snapshots (fields.hh and the tree's own: in_snapshots, with its units), in registry order, but
/// for walls not those of moving particles only, and not those of a feature the run lacks (the
/// potential without self-gravity). Densities are per D-volume (M L^-D).
template<int D>
std::vector<snapshot_quantity> snapshot_quantities(const simulation<D>& s, bool walls) {
  std::vector<snapshot_quantity> quantities;
  for (const auto& field : flecsi_lite::data::registered_fields<particle_tree<D>>()) {
    const auto& p = field.persistence;
    if (p.swift().snapshot_dataset.empty() || (walls && p.swift().moving_particles_only)) continue;
    if (!p.feature().empty() && !has_feature(s, p.feature())) continue;
    quantities.push_back({p.swift().snapshot_dataset, field.datasets, p.units(), p.swift().description});
  }
  return quantities;
}

/// The CGS value of one code unit of a quantity (SWIFT's units_general_cgs_conversion_factor).
inline double cgs_factor(const unit_system& u, const unit_exponents& e) {
  return std::pow(u.mass_in_cgs, double(e.mass)) * std::pow(u.length_in_cgs, double(e.length)) *
         std::pow(u.time_in_cgs, double(e.time));
}

/// SWIFT's "Expression for physical CGS units": "U_M U_L^-3  [ g cm^-3 ]", "[ - ] " for none.
inline std::string cgs_expression(const unit_exponents& e) {
  const float powers[3] = {e.mass, e.length, e.time};
  const char* code[3] = {"U_M", "U_L", "U_t"};
  const char* cgs[3] = {"g", "cm", "s"};
  if (powers[0] == 0 && powers[1] == 0 && powers[2] == 0) return "[ - ] ";
  const auto term = [](const char* symbol, float power) {
    char text[32];
    if (power == 1)
      std::snprintf(text, sizeof text, "%s ", symbol);
    else if (std::remainder(power, 1.0f) == 0)
      std::snprintf(text, sizeof text, "%s^%d ", symbol, int(power));
    else
      std::snprintf(text, sizeof text, "%s^%7.4f ", symbol, double(power));
    return std::string(text);
  };
  std::string text, bracket = " [ ";
  for (int k = 0; k < 3; ++k)
    if (powers[k] != 0) text += term(code[k], powers[k]), bracket += term(cgs[k], powers[k]);
  return text + bracket + "]";
}

/// The unit attributes SWIFT writes on every dataset (parallel_io.c, prepare_array_parallel), no
/// cosmology: scale-factor exponent 0, the physical factor equal to the comoving one.
inline flecsi_lite::io::snapshot_attributes unit_attributes(const unit_system& u, const snapshot_quantity& q) {
  using floats = std::vector<float>;
  using doubles = std::vector<double>;
  const double factor = cgs_factor(u, q.units);
  return {{"U_M exponent", floats{q.units.mass}},
          {"U_L exponent", floats{q.units.length}},
          {"U_t exponent", floats{q.units.time}},
          {"U_I exponent", floats{0}},
          {"U_T exponent", floats{0}},
          {"h-scale exponent", floats{0}},
          {"a-scale exponent", floats{0}},
          {"Expression for physical CGS units", cgs_expression(q.units)},
          {"Lossy compression filter", std::string("None")},
          {"Value stored as physical", std::vector<std::int32_t>{1}},
          {"Property can be converted to comoving", std::vector<std::int32_t>{0}},
          {"Conversion factor to CGS (not including cosmological corrections)", doubles{factor}},
          {"Conversion factor to physical CGS (including cosmological corrections)", doubles{factor}},
          {"Description", q.description}};
}

/// The units in the root attributes of the H5Part output: SWIFT's names of the base units
/// ("Unit mass in cgs (U_M)", "Unit length in cgs (U_L)", "Unit time in cgs (U_t)") and, for each
/// H5Part output dataset of a snapshot quantity, "<dataset> conversion factor to CGS" (one code
/// unit in CGS) and "<dataset> CGS units" (cgs_expression, e.g. "U_M U_L^-3  [ g cm^-3 ]").
/// Walls share the fluid's.
template<int D>
std::vector<std::pair<std::string, flecsi_lite::io::attribute_value>> h5part_unit_attributes(const unit_system& u,
                                                                                             const simulation<D>& s) {
  std::vector<std::pair<std::string, flecsi_lite::io::attribute_value>> out = {
    {"Unit mass in cgs (U_M)", u.mass_in_cgs},
    {"Unit length in cgs (U_L)", u.length_in_cgs},
    {"Unit time in cgs (U_t)", u.time_in_cgs}};
  for (const auto& field : files_fields(s)) {
    const auto& p = field.persistence;
    if (p.swift().snapshot_dataset.empty() || !p.has(flecsi_lite::data::role::output)) continue;
    for (const auto& dataset : field.datasets) {
      out.push_back({dataset + " conversion factor to CGS", cgs_factor(u, p.units())});
      out.push_back({dataset + " CGS units", cgs_expression(p.units())});
    }
  }
  return out;
}

/// The Units (and InternalCodeUnits) group: SWIFT's io_write_unit_system.
inline flecsi_lite::io::snapshot_attributes units_group(const unit_system& u) {
  using doubles = std::vector<double>;
  return {{"Unit mass in cgs (U_M)", doubles{u.mass_in_cgs}},
          {"Unit length in cgs (U_L)", doubles{u.length_in_cgs}},
          {"Unit time in cgs (U_t)", doubles{u.time_in_cgs}},
          {"Unit current in cgs (U_I)", doubles{1}},
          {"Unit temperature in cgs (U_T)", doubles{1}}};
}

}  // namespace flecsph::sph
