// Access privileges a task declares for each region of a field (FleCSI's ro/wo/rw/na).
// Regions: OWNED (exclusive + shared entities, this rank's values) and GHOST (copies of
// entities other ranks own). From the privileges the executor derives task dependencies and
// when ghost values must be copied.
#pragma once

namespace flecsi_lite {

enum privilege : unsigned char {
  na = 0,  // no access
  ro = 1,  // read only
  wo = 2,  // write only: previous values are not read
  rw = 3,  // read and write
};

constexpr bool reads(privilege p) { return p == ro || p == rw; }
constexpr bool writes(privilege p) { return p == wo || p == rw; }
constexpr const char* privilege_name(privilege p) { return p == na ? "na" : p == ro ? "ro" : p == wo ? "wo" : "rw"; }

enum class region : unsigned char { owned = 0, ghost = 1 };

}  // namespace flecsi_lite
