// Initial particles from a SWIFT-format initial-conditions file, the layout the makeIC.py scripts
// of SWIFT's examples write (examples/HydroTests/*/makeIC.py; SWIFT's src/hydro/*/hydro_io.h
// names the datasets it reads): Header with NumPart_Total (and NumPart_Total_HighWord),
// optionally Dimension, NumFilesPerSnapshot and Flag_Entropy_ICs; PartType0 with
//
//   required   Coordinates (N x 3; the columns beyond the dimension are ignored), Masses,
//              SmoothingLength, InternalEnergy
//   optional   Velocities (N x 3; 0), ParticleIDs (the index), Density (an initial guess only)
//
// or a snapshot's plural names (SmoothingLengths, InternalEnergies, Densities): SWIFT's snapshots
// and ours (snapshot_output.hh) read back as initial data; ours with walls hold them in PartType2
// and are refused as particles of another type (their H5Part output holds the walls' kind).
//
// read in parallel (each rank its block, io::gadget_reader) and checked by the same fields' rules
// as H5Part initial data (particle_input.hh). SmoothingLength is taken as our h (support 2 h):
// with adaptive_smoothing_length it is only the first guess of the density iteration; SWIFT's h
// is support / kernel_gamma (Dehnen & Aly 2012), 2 / kernel_gamma of ours. Refused, naming the
// file and the attribute: another dimension, several files, entropies instead of energies
// (Flag_Entropy_ICs), particles of other types, and a Units group other than the run's units.
// Header fields that disagree with the data (NumPart_ThisFile, MassTable, a PartType1..5 group
// without its count) are refused (swift_header_checks.hh). Header/BoxSize and Time are not used:
// the app's problem sets the domain, the run starts at 0; particles outside the run's periodic box
// (SWIFT's [0, BoxSize) against a box centred elsewhere) are refused with the box and the shift.
#pragma once

#include "specialization/sph/files/particle_input.hh"
#include "specialization/sph/files/snapshot_settings.hh"
#include "specialization/sph/files/swift_header_checks.hh"
#include "specialization/sph/model/fields.hh"

#include "flecsi_lite/data.hh"
#include "flecsi_lite/io.hh"

#include <cmath>
#include <cstdint>
#include <map>
#include <memory>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace flecsph::sph {

/// Our field datasets in SWIFT's initial-conditions names, as the fields' definitions give them
/// (model/fields.hh and the tree's own: in_swift_initial_conditions), or (snapshot_names) the
/// same fields under their snapshot names, the plural names of SWIFT's snapshots, which ours
/// share (SmoothingLengths, InternalEnergies, Densities); a vector's component k (k < D) is
/// column k of the N x 3 dataset.
template<int D>
std::map<std::string, flecsi_lite::io::gadget_reader::column> swift_initial_columns(bool snapshot_names = false) {
  std::map<std::string, flecsi_lite::io::gadget_reader::column> columns;
  for (const auto& field : flecsi_lite::data::registered_fields<particle_tree<D>>()) {
    const auto& naming = field.persistence.swift();
    if (naming.initial_conditions_dataset.empty()) continue;
    const std::string& name = snapshot_names ? naming.snapshot_dataset : naming.initial_conditions_dataset;
    for (int k = 0; k < field.components; ++k) columns[field.datasets[k]] = {name, k};
  }
  return columns;
}

namespace detail {
/// The fewest digits that read back as `value` (3.0857e+21, not 3.0856999999999999e+21).
inline std::string shortest(double value) {
  for (int digits = 6;; ++digits) {
    std::ostringstream text;
    text.precision(digits);
    text << value;
    if (digits == 17 || std::stod(text.str()) == value) return text.str();
  }
}

/// The Header's checks (see the file's head); `in` holds PartType0.
template<int D>
void check_swift_header(const flecsi_lite::io::gadget_reader& in, const unit_system& units) {
  const std::string file = "'" + in.path() + "'";
  const auto refuse = [&](const std::string& why) { throw std::invalid_argument(file + " " + why); };
  if (in.has_attribute("Header", "Dimension")) {
    const double dimension = in.numbers("Header", "Dimension").front();
    if (dimension != D)
      refuse("Header/Dimension = " + std::to_string(static_cast<long>(dimension)) + ", but this run is " +
             std::to_string(D) + "D: use the app's " + std::to_string(static_cast<long>(dimension)) +
             "D parameter file or a " + std::to_string(D) + "D initial-conditions file");
  }
  if (in.has_attribute("Header", "NumFilesPerSnapshot") && in.numbers("Header", "NumFilesPerSnapshot").front() != 1)
    refuse("is one of several files (Header/NumFilesPerSnapshot > 1): give a single-file initial-conditions file");
  if (in.has_attribute("Header", "Flag_Entropy_ICs"))
    for (const double flag : in.numbers("Header", "Flag_Entropy_ICs"))
      if (flag != 0)
        refuse(
          "has Header/Flag_Entropy_ICs = 1 (InternalEnergy holds entropies): give internal energies "
          "and Flag_Entropy_ICs = 0");
  const auto low = in.numbers("Header", "NumPart_Total");
  std::vector<double> high(low.size(), 0.0);
  if (in.has_attribute("Header", "NumPart_Total_HighWord")) high = in.numbers("Header", "NumPart_Total_HighWord");
  for (std::size_t type = 0; type < low.size(); ++type) {
    const double total = low[type] + (type < high.size() ? high[type] : 0.0) * 4294967296.0;
    if (type == 0 && total != static_cast<double>(in.particle_count()))
      refuse("Header/NumPart_Total[0] = " + std::to_string(static_cast<std::uint64_t>(total)) +
             " but PartType0 holds " + std::to_string(in.particle_count()) + " particles");
    if (type > 0 && total != 0)
      refuse("holds " + std::to_string(static_cast<std::uint64_t>(total)) + " particles of type " +
             std::to_string(type) + " (Header/NumPart_Total[" + std::to_string(type) +
             "]): only gas (PartType0) initial conditions are read");
  }
  check_swift_counts_and_masses(in);
  if (!in.has_group("Units")) return;  // SWIFT's internal units are then the file's
  const struct {
    const char* name;
    double run;
    const char* key;
  } bases[] = {{"Unit mass in cgs (U_M)", units.mass_in_cgs, "unit_mass_in_cgs"},
               {"Unit length in cgs (U_L)", units.length_in_cgs, "unit_length_in_cgs"},
               {"Unit time in cgs (U_t)", units.time_in_cgs, "unit_time_in_cgs"}};
  for (const auto& base : bases) {
    const double value = in.numbers("Units", base.name).front();
    if (std::abs(value - base.run) > 1e-12 * std::abs(base.run))
      refuse("has Units/" + std::string(base.name) + " = " + shortest(value) + " but the run's " + base.key + " = " +
             shortest(base.run) + ": set " + base.key + " = " + shortest(value) +
             " (the run then works in the file's units)");
  }
}
}  // namespace detail

/// Collective: creates the particles of `s` from the SWIFT-format initial conditions `path` (this
/// rank's block, with their initial fields), after the Header's checks against dimension D and
/// the run's `units`. The tree settings must be set. Returns the particle count.
template<int D>
std::uint64_t read_swift_initial_data(simulation<D>& s, const std::string& path, const unit_system& units) {
  using flecsi_lite::io::gadget_reader;
  auto file = std::make_unique<const gadget_reader>(path, "PartType0", swift_initial_columns<D>());
  // A snapshot (SWIFT's or ours) names h and u in the plural: read it as initial conditions too.
  if (!file->has_column("h") && !file->has_column("u")) {
    file.reset();
    file = std::make_unique<const gadget_reader>(path, "PartType0", swift_initial_columns<D>(true));
  }
  const gadget_reader& in = *file;
  detail::check_swift_header<D>(in, units);
  if (in.particle_count() == 0) throw std::invalid_argument(in.where() + " holds no particles");
  create_particles(s, in.block().count);
  detail::check_initial_ids(in);  // before the fields, as read_particles
  flecsi_lite::data::read_fields(*s.particles, in, flecsi_lite::data::role::initial);
  try {
    detail::check_particle_set(s, in.where());
  } catch (const std::invalid_argument& e) {
    // The tree's refusal says nothing of the file: say which box and what to change.
    if (std::string(e.what()).rfind("ntree: particles outside the periodic box", 0) != 0) throw;
    throw std::invalid_argument(detail::outside_periodic_box<D>(in, s.tree_settings));
  }
  return in.particle_count();
}

}  // namespace flecsph::sph
