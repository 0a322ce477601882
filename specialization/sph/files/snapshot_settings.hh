// The output format keys of an SPH run (H5Part, GADGET/SWIFT-layout snapshots, or both) and its
// unit system: the code units' values in CGS, as SWIFT's InternalUnitSystem states them.
#pragma once

#include "flecsi_lite/runtime.hh"

#include <string>

namespace flecsph::sph {

/// What an output step writes: the H5Part series (output_file), one snapshot per output time
/// (`<stem>_NNNN.hdf5` beside output_file, with the index `<stem>.xdmf`), or both.
enum class output_format { h5part, snapshots, both };

inline const flecsi_lite::runtime::name_table<output_format>& output_format_names() {
  static const flecsi_lite::runtime::name_table<output_format> names{
    "output format",
    {{"h5part", output_format::h5part}, {"snapshots", output_format::snapshots}, {"both", output_format::both}}};
  return names;
}

/// The code units in CGS: every quantity of the run is a number times M^a L^b T^c of these
/// (code units by default: 1 g, 1 cm, 1 s; the equations have no constant that fixes them).
struct unit_system {
  double mass_in_cgs = 1;    ///< grams per code mass unit (SWIFT's UnitMass_in_cgs)
  double length_in_cgs = 1;  ///< centimetres per code length unit
  double time_in_cgs = 1;    ///< seconds per code time unit
};

struct snapshot_settings {
  output_format format = output_format::h5part;
  unit_system units{};
};

inline bool writes_h5part(const snapshot_settings& s) { return s.format != output_format::snapshots; }
inline bool writes_snapshots(const snapshot_settings& s) { return s.format != output_format::h5part; }

/// The keys output_format, unit_mass_in_cgs, unit_length_in_cgs and unit_time_in_cgs.
inline const flecsi_lite::runtime::parameter_block<snapshot_settings>& snapshot_parameters() {
  static const auto block = [] {
    using flecsi_lite::runtime::member;
    flecsi_lite::runtime::parameter_block<snapshot_settings> keys;
    keys.choice("output_format", &snapshot_settings::format, output_format_names(),
                "h5part: output_file; snapshots: GADGET/SWIFT HDF5 <stem>_NNNN.hdf5 and <stem>.xdmf beside "
                "output_file; both");
    keys
      .real("unit_mass_in_cgs", member(&snapshot_settings::units, &unit_system::mass_in_cgs),
            "the code unit of mass in grams (written in the snapshots' Units)")
      .greater_than(0)
      .at_most(1e100);
    keys
      .real("unit_length_in_cgs", member(&snapshot_settings::units, &unit_system::length_in_cgs),
            "the code unit of length in centimetres")
      .greater_than(0)
      .at_most(1e100);
    keys
      .real("unit_time_in_cgs", member(&snapshot_settings::units, &unit_system::time_in_cgs),
            "the code unit of time in seconds")
      .greater_than(0)
      .at_most(1e100);
    return keys;
  }();
  return block;
}

}  // namespace flecsph::sph
