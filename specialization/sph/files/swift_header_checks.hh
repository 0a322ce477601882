// The Header fields of a SWIFT initial-conditions file that must agree with its particles (issue
// 38, item 9): NumPart_ThisFile (GADGET's per-file counts, Springel 2005 format), MassTable (in
// GADGET a non-zero entry replaces the Masses dataset of its type; SWIFT reads Masses), groups
// PartType1..5 (read only when their NumPart_Total says so, so one without a count is an
// inconsistent file), and the [0, BoxSize) box of SWIFT's makeIC.py scripts against a run whose
// periodic box starts elsewhere. Each refusal names the file, the group and the field.
#pragma once

#include "flecsi_lite/io.hh"
#include "flecsi_lite/topology/ntree.hh"

#include <cstdint>
#include <sstream>
#include <stdexcept>
#include <string>
#include <vector>

namespace flecsph::sph::detail {

/// Throws std::invalid_argument (exit status 3) on the first Header field that disagrees with
/// PartType0 of `in`.
inline void check_swift_counts_and_masses(const flecsi_lite::io::gadget_reader& in) {
  const std::string file = "'" + in.path() + "'";
  const auto refuse = [&](const std::string& why) { throw std::invalid_argument(file + " " + why); };
  if (in.has_attribute("Header", "NumPart_ThisFile")) {
    const auto here = in.numbers("Header", "NumPart_ThisFile");
    for (std::size_t type = 0; type < here.size(); ++type) {
      if (type == 0 && here[0] != static_cast<double>(in.particle_count()))
        refuse("has Header/NumPart_ThisFile[0] = " + std::to_string(static_cast<std::uint64_t>(here[0])) +
               " but PartType0 holds " + std::to_string(in.particle_count()) +
               " particles: the header and the data disagree");
      if (type > 0 && here[type] != 0)
        refuse("has Header/NumPart_ThisFile[" + std::to_string(type) +
               "] = " + std::to_string(static_cast<std::uint64_t>(here[type])) +
               ": only gas (PartType0) initial conditions are read");
    }
  }
  if (in.has_attribute("Header", "MassTable")) {
    const auto table = in.numbers("Header", "MassTable");
    if (!table.empty() && table[0] != 0) {
      std::ostringstream value;
      value.precision(17);
      value << table[0];
      refuse("has Header/MassTable[0] = " + value.str() +
             ": in the GADGET layout a non-zero entry gives every gas particle that mass instead of "
             "PartType0/Masses, which is read here; set MassTable[0] = 0 (masses from Masses)");
    }
  }
  const auto totals = in.numbers("Header", "NumPart_Total");
  for (int type = 1; type <= 5; ++type) {
    const std::string group = "PartType" + std::to_string(type);
    const bool counted = static_cast<std::size_t>(type) < totals.size() && totals[type] != 0;
    if (in.has_group(group) && !counted)
      refuse("has a group " + group + " but Header/NumPart_Total[" + std::to_string(type) +
             "] = 0: the header and the data disagree (only gas, PartType0, is read: remove " + group + ")");
  }
}

/// The message for particles outside the run's periodic box (the tree's refusal), with what to
/// change: SWIFT's makeIC.py scripts place particles in [0, BoxSize).
template<int D>
std::string outside_periodic_box(const flecsi_lite::io::gadget_reader& in,
                                 const flecsi_lite::topology::ntree::ntree_config<D>& tree) {
  std::ostringstream message;
  message.precision(17);
  message << "'" << in.path() << "' PartType0/Coordinates lie outside this run's periodic box";
  for (int k = 0; k < D; ++k)
    if (tree.periodic[k] && tree.fixed_box)
      message << "; axis " << k << ": [" << tree.fixed_box->lo[k] << ", " << tree.fixed_box->hi[k] << ")";
  if (in.has_attribute("Header", "BoxSize")) {
    message << "; the file's Header/BoxSize =";
    for (const double size : in.numbers("Header", "BoxSize")) message << " " << size;
  }
  message << ". SWIFT's makeIC.py scripts write positions in [0, BoxSize): shift Coordinates by the run's lower "
             "corner (add it to each axis), or choose the app's box to match the file";
  return message.str();
}

}  // namespace flecsph::sph::detail
