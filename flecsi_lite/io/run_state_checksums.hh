// Checksums of a checkpoint's run state (issue 38, item 3): a restart from a changed clock or
// counter continues another run (a global-step dt one ulp off, a step counter that no longer
// matches the time), and nothing else in the file tells the changed value from the written one.
// Each value (Step#0's time, step and dt, every root attribute state:*) is hashed with 64-bit
// FNV-1a (Fowler, Noll and Vo; IETF draft-eastlake-fnv) over its kind and its exact bytes, and
// the hashes are stored as the checkpoint's root attribute "checksums", one "<name> <hex>" line
// per value. This detects values changed by hand or by a tool, not a deliberate forgery (anyone
// can recompute the hashes); the particle datasets are checked by their own consistency checks.
#pragma once

#include "flecsi_lite/io/attribute_value.hh"

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace flecsi_lite::io {

/// The root attribute that holds the checksums.
inline constexpr const char* checksums_attribute = "checksums";

/// The values under checksum, by the name the checksum lines use ("time", "step", "dt" for
/// Step#0's attributes, "state:<name>" for the run state).
using checked_values = std::map<std::string, attribute_value>;

/// 64-bit FNV-1a of the value's kind (one byte: 0 integer, 1 real, 2 string) and its bytes (the
/// integer's or the double's 8 bytes, least significant first; the string's characters).
std::uint64_t fnv1a(const attribute_value& value);

/// The "checksums" text of `values`: "<name> <16 hex digits>\n" per value, in name order.
std::string checksums_text(const checked_values& values);

/// The names of the values that differ from `checksums` (a changed value, a value without a line,
/// a line without a value), in name order; empty when all match. A line that is not
/// "<name> <16 hex digits>" counts as a changed value named as written.
std::vector<std::string> changed_values(const std::string& checksums, const checked_values& values);

}  // namespace flecsi_lite::io
