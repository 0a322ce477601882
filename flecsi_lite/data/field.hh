// Fields: named per-entity values defined once per topology type and stored per instance.
//
//   const field<double>::definition<narray> temperature{"temperature"};   // once, at namespace scope
//   const field<double>::definition<narray> energy{"e", persist::output().restart()};  // persists
//   execute<step>(temperature(mesh));                                       // a reference to mesh's storage
//   void step(field<double>::accessor<rw, ro> t);                           // privileges: owned rw, ghost ro
#pragma once

#include "flecsi_lite/data/field_registry.hh"
#include "flecsi_lite/data/persistence.hh"
#include "flecsi_lite/data/privilege.hh"
#include "flecsi_lite/data/topology_base.hh"

#include <cassert>
#include <string>
#include <type_traits>
#include <vector>

namespace flecsi_lite {

/// What a task sees of a field: owned entities [0, owned_size()) and, when the ghost privilege
/// is not na, ghost entities [owned_size(), size()).
template<class T, privilege Owned, privilege Ghost>
class accessor {
public:
  using value_type = T;
  using element = std::conditional_t<writes(Owned) || writes(Ghost), T, const T>;
  using view_type = typename data::field_storage<T>::view_type;
  static constexpr privilege owned_privilege = Owned;
  static constexpr privilege ghost_privilege = Ghost;

  accessor() = default;
  accessor(view_type view, std::size_t owned, std::size_t ghosts)
    : view_(view), owned_(owned), size_(owned + (Ghost == na ? 0 : ghosts)) {}

  KOKKOS_INLINE_FUNCTION element& operator()(std::size_t i) const {
    assert(i < size_ && "entity outside the regions this accessor may touch");
    return view_(i);
  }
  KOKKOS_INLINE_FUNCTION element& operator[](std::size_t i) const { return (*this)(i); }
  KOKKOS_INLINE_FUNCTION std::size_t owned_size() const { return owned_; }
  KOKKOS_INLINE_FUNCTION std::size_t ghost_size() const { return size_ - owned_; }
  /// Entities this accessor may touch (owned, plus ghosts unless the ghost privilege is na).
  KOKKOS_INLINE_FUNCTION std::size_t size() const { return size_; }
  element* data() const { return view_.data(); }

private:
  view_type view_;
  std::size_t owned_ = 0, size_ = 0;
};

/// A field bound to one topology instance; what execute() takes as an argument.
template<class T, class Topo>
class field_reference {
public:
  using value_type = T;
  using topology_type = Topo;
  field_reference(Topo& topology, std::size_t id) : topology_(&topology), id_(id) {}

  Topo& topology() const { return *topology_; }
  std::size_t id() const { return id_; }
  const std::string& name() const { return data::registered_fields<Topo>()[id_].name; }
  data::field_storage<T>& storage() const { return topology_->template storage<T>(id_, name()); }

  template<privilege Owned, privilege Ghost>
  accessor<T, Owned, Ghost> make_accessor() const {
    return {storage().view(), topology_->owned_size(), topology_->ghost_size()};
  }

private:
  Topo* topology_;
  std::size_t id_;
};

template<class T>
struct field {
  using value_type = T;
  template<privilege Owned, privilege Ghost = na>
  using accessor = flecsi_lite::accessor<T, Owned, Ghost>;
  template<class Topo>
  using reference = field_reference<T, Topo>;

  /// Declares a field on every instance of topology type Topo, with its persistence (none:
  /// the field lives in memory only).
  template<class Topo>
  class definition {
  public:
    explicit definition(std::string name, data::persistence persistence = {})
      : id_(data::registered_fields<Topo>().size()) {
      auto entry = data::make_registered_field<T>(std::move(name), std::move(persistence));
      data::registered_fields<Topo>().push_back(std::move(entry));
    }
    reference<Topo> operator()(Topo& topology) const { return {topology, id_}; }
    std::size_t id() const { return id_; }
    const std::string& name() const { return data::registered_fields<Topo>()[id_].name; }
    const data::persistence& persistence() const { return data::registered_fields<Topo>()[id_].persistence; }

  private:
    std::size_t id_;
  };
};

} // namespace flecsi_lite
