#include "flecsi_lite/data/topology_base.hh"

#include "flecsi_lite/data/layout_listener.hh"
#include "flecsi_lite/data/tracked.hh"

#include <atomic>

namespace flecsi_lite::data {
namespace {
std::atomic<std::uint64_t> next_instance_id{1};
layout_listener* listener = nullptr;
}  // namespace

std::uint64_t new_instance_id() { return next_instance_id++; }
void set_layout_listener(layout_listener* l) { listener = l; }
layout_listener* current_layout_listener() { return listener; }

topology_base::topology_base() : instance_id_(new_instance_id()) {}

topology_base::~topology_base() {
  if (listener) listener->topology_destroyed(instance_id_);
}

void topology_base::set_sizes(std::size_t owned, std::size_t ghosts) {
  if (listener) listener->before_layout_change(instance_id_);
  owned_ = owned;
  ghosts_ = ghosts;
  for (auto& s : storages_)
    if (s) s->resize(owned_ + ghosts_);
  layout_changed();
}

void topology_base::reorder_owned(const std::vector<std::size_t>& order, std::size_t ghosts) {
  if (listener) listener->before_layout_change(instance_id_);
  for (auto& s : storages_)
    if (s) s->gather(order, ghosts);
  owned_ = order.size();
  ghosts_ = ghosts;
  layout_changed();
}

void topology_base::set_plan(ghost_plan plan) {
  if (listener) listener->before_layout_change(instance_id_);
  plan_ = std::move(plan);
  layout_changed();
}

void topology_base::layout_changed() {
  ++layout_version_;
  if (listener) listener->after_layout_change(instance_id_);
}

}  // namespace flecsi_lite::data
