// Tracked objects: data other than fields that tasks share, such as neighbour lists and trees. A
// task declares a privilege on one (tracked<T>::accessor<ro> and so on) and the executor orders
// it against the other launches that use the object, as it does for a field's owned region
// (read after write, write after read, write after write), so no hand-placed wait keeps it safe.
//
//   flecsi_lite::tracked<lists> neighbours{"neighbour lists"};
//   void search(tracked<lists>::accessor<wo> out, ...);     // writes the lists
//   void density(tracked<lists>::accessor<ro> in, ...);     // runs after the search
//   execute<search>(neighbours, ...);  execute<density>(neighbours, ...);
#pragma once

#include "flecsi_lite/data/layout_listener.hh"
#include "flecsi_lite/data/privilege.hh"

#include <cstdint>
#include <string>
#include <type_traits>
#include <utility>

namespace flecsi_lite {

namespace data {
/// A fresh identity for the executor's bookkeeping (shared with topology instances).
std::uint64_t new_instance_id();
}  // namespace data

/// What a task sees of a tracked object: a const reference with ro, a mutable one with wo / rw.
template<class T, privilege P>
class tracked_accessor {
  static_assert(P != na, "a task that does not use a tracked object takes no accessor to it");

 public:
  using value_type = T;
  using element = std::conditional_t<writes(P), T, const T>;
  static constexpr privilege object_privilege = P;

  explicit tracked_accessor(element& value) : value_(&value) {}
  element& operator*() const { return *value_; }
  element* operator->() const { return value_; }

 private:
  element* value_;
};

/// Owns a T that tasks reach only through accessors; host() is the way in outside tasks.
template<class T>
class tracked {
 public:
  using value_type = T;
  template<privilege P>
  using accessor = tracked_accessor<T, P>;

  template<class... Args>
  explicit tracked(std::string name, Args&&... args)
      : value_(std::forward<Args>(args)...), name_(std::move(name)), id_(data::new_instance_id()) {}
  tracked(const tracked&) = delete;
  tracked& operator=(const tracked&) = delete;
  ~tracked() {
    if (auto* listener = data::current_layout_listener()) listener->topology_destroyed(id_);
  }

  /// The object outside tasks, once every pending launch has finished (they may use it).
  T& host() {
    wait_for_tasks();
    return value_;
  }
  const T& host() const {
    wait_for_tasks();
    return value_;
  }

  const std::string& name() const { return name_; }
  std::uint64_t instance_id() const { return id_; }
  /// The object itself, for the executor's binder only (tasks get accessors, hosts host()).
  T& launch_value() { return value_; }
  const T& launch_value() const { return value_; }

 private:
  void wait_for_tasks() const {
    if (auto* listener = data::current_layout_listener()) listener->before_host_access(id_);
  }

  T value_;
  std::string name_;
  std::uint64_t id_;
};

}  // namespace flecsi_lite
