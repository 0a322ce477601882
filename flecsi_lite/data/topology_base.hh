// What every topology instance shares: an index space of OWNED entities followed by GHOST
// entities, the storage of every field defined on it, and the ghost plan that says which owned
// entities other ranks need. Topologies (narray, ntree, ...) derive from it and decide sizes,
// order and plan; the framework keeps every field consistent with them.
#pragma once

#include "flecsi_lite/data/field_storage.hh"
#include "flecsi_lite/data/ghost_plan.hh"

#include <cstdint>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace flecsi_lite::data {

class topology_base {
 public:
  topology_base();
  topology_base(const topology_base&) = delete;
  topology_base& operator=(const topology_base&) = delete;
  virtual ~topology_base();

  /// Unique per instance, for the executor's bookkeeping.
  std::uint64_t instance_id() const { return instance_id_; }
  std::size_t owned_size() const { return owned_; }
  std::size_t ghost_size() const { return ghosts_; }
  std::size_t total_size() const { return owned_ + ghosts_; }
  const ghost_plan& plan() const { return plan_; }
  /// Changes whenever sizes, order or plan change: all ghost values are stale then.
  std::uint64_t layout_version() const { return layout_version_; }

  /// Storage of field `id` (created on first use with the current size).
  template<class T>
  field_storage<T>& storage(std::size_t id, const std::string& name) {
    if (id >= storages_.size()) storages_.resize(id + 1);
    if (!storages_[id]) storages_[id] = std::make_unique<field_storage<T>>(name, total_size());
    auto* typed = dynamic_cast<field_storage<T>*>(storages_[id].get());
    if (!typed) throw std::logic_error("field '" + name + "' used with two different types");
    return *typed;
  }
  /// Every field storage created so far (null entries for fields never used on this instance).
  const std::vector<std::unique_ptr<field_storage_base>>& storages() const { return storages_; }

 protected:
  // These first wait for every pending task (fields change under them), then change the layout
  // of every field at once.

  /// New sizes: owned values [0, min(old, new)) are kept, ghost values are stale.
  void set_sizes(std::size_t owned, std::size_t ghosts);
  /// Reorders or selects owned entities of every field: new[i] = old[order[i]]; ghosts stale.
  void reorder_owned(const std::vector<std::size_t>& order, std::size_t ghosts);
  void set_plan(ghost_plan plan);

 private:
  void layout_changed();

  std::uint64_t instance_id_;
  std::size_t owned_ = 0, ghosts_ = 0;
  std::uint64_t layout_version_ = 0;
  ghost_plan plan_;
  std::vector<std::unique_ptr<field_storage_base>> storages_;
};

}  // namespace flecsi_lite::data
