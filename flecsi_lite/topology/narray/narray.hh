// narray: a 1-D index space of global_size entities, split into contiguous blocks over the
// ranks, with `halo` ghost entities on each side (periodic or not). The smallest distributed
// topology: it exercises fields, ghost copies and the executor without a tree (like FleCSI's
// narray). Local layout: owned entities [0, owned_size()), then the left halo, then the right.
#pragma once

#include "flecsi_lite/data/topology_base.hh"

#include <cstdint>

namespace flecsi_lite::topology {

class narray : public data::topology_base {
 public:
  /// Collective. Throws std::invalid_argument when a rank's block is smaller than the halo.
  narray(std::size_t global_size, std::size_t halo, bool periodic);

  std::size_t global_size() const { return global_size_; }
  std::size_t halo() const { return halo_; }
  bool periodic() const { return periodic_; }
  /// Global index of owned entity 0.
  std::size_t first_global() const { return first_; }
  /// Global index of the entity stored at local index `local` (owned or ghost).
  std::size_t global_index(std::size_t local) const;
  /// Local index of the entity `offset` places from owned entity i (|offset| <= halo), or
  /// npos beyond a non-periodic boundary.
  std::size_t neighbor(std::size_t i, long offset) const;
  static constexpr std::size_t npos = static_cast<std::size_t>(-1);

 private:
  std::size_t global_size_, halo_, first_ = 0;
  std::size_t left_ghosts_ = 0, right_ghosts_ = 0;
  bool periodic_;
};

}  // namespace flecsi_lite::topology
