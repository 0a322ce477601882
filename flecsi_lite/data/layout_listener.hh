// How a topology tells the execution layer that it is about to change (sizes, order, ghost plan):
// pending tasks must finish first, and ghost values become stale after. The executor installs
// itself as the listener, keeping the data layer free of any execution dependency. Tracked objects
// (tracked.hh) use the same channel: their host access waits for pending tasks, their end drops
// the executor's bookkeeping of them.
#pragma once

#include <cstdint>

namespace flecsi_lite::data {

class layout_listener {
 public:
  virtual ~layout_listener() = default;
  virtual void before_layout_change(std::uint64_t topology_id) = 0;
  virtual void after_layout_change(std::uint64_t topology_id) = 0;
  virtual void topology_destroyed(std::uint64_t topology_id) = 0;
  /// Before the host touches an object that tasks may be using.
  virtual void before_host_access(std::uint64_t object_id) = 0;
};

void set_layout_listener(layout_listener* listener);
layout_listener* current_layout_listener();

}  // namespace flecsi_lite::data
