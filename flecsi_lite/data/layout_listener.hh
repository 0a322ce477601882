// How a topology tells the execution layer that it is about to change (sizes, order, ghost plan):
// pending tasks must finish first, and ghost values become stale after. The executor installs
// itself as the listener, keeping the data layer free of any execution dependency.
#pragma once

#include <cstdint>

namespace flecsi_lite::data {

class layout_listener {
public:
  virtual ~layout_listener() = default;
  virtual void before_layout_change(std::uint64_t topology_id) = 0;
  virtual void after_layout_change(std::uint64_t topology_id) = 0;
  virtual void topology_destroyed(std::uint64_t topology_id) = 0;
};

void set_layout_listener(layout_listener* listener);
layout_listener* current_layout_listener();

} // namespace flecsi_lite::data
