// Fields: named per-entity values defined once per topology type and stored per instance.
//
//   const field<double>::definition<narray> temperature{"temperature"};   // once, at namespace scope
//   const field<double>::definition<narray> energy{"e", persist::output().restart()};  // persists
//   execute<step>(temperature(mesh));                                       // a reference to mesh's storage
//   void step(field<double>::accessor<rw, ro> t);  // owned rw (t.owned(i) = ...), ghost ro (t(i) reads all)
#pragma once

#include "flecsi_lite/data/detail/access_error.hh"
#include "flecsi_lite/data/field_registry.hh"
#include "flecsi_lite/data/persistence.hh"
#include "flecsi_lite/data/privilege.hh"
#include "flecsi_lite/data/topology_base.hh"

#include <stdexcept>
#include <string>
#include <type_traits>
#include <vector>

namespace flecsi_lite {

/// What a task sees of a field: owned entities [0, owned_size()) and, when the ghost privilege
/// is not na, ghost entities [owned_size(), size()). Privileges are enforced per region:
///   - a region without write privilege is reached through const references only: writing
///     through an accessor<ro> or accessor<ro, ro> does not compile;
///   - a region with privilege na is out of reach: owned(i) / ghost(j) / data() of an na region do
///     not compile; f(i) of an accessor<na, G> on an owned entity throws, naming the field;
///   - f(i) writes only where every region it spans is writable (accessor<rw, ro>: f(i) reads,
///     f.owned(i) writes the owned values, and the ghosts stay read-only).
/// Debug builds also check every index against the accessor's span.
template<class T, privilege Owned, privilege Ghost>
class accessor {
  template<privilege P>
  using region_element = std::conditional_t<writes(P), T, const T>;

 public:
  using value_type = T;
  /// Of f(i): writable only when each region it spans is writable.
  using element =
    std::conditional_t<Ghost == na, region_element<Owned>,
                       std::conditional_t<Owned == na, region_element<Ghost>,
                                          std::conditional_t<writes(Owned) && writes(Ghost), T, const T>>>;
  using owned_element = region_element<Owned>;
  using ghost_element = region_element<Ghost>;
  using view_type = typename data::field_storage<T>::view_type;
  static constexpr privilege owned_privilege = Owned;
  static constexpr privilege ghost_privilege = Ghost;

  accessor() = default;
  accessor(view_type view, std::size_t owned, std::size_t ghosts, const std::string* name = nullptr)
      : view_(view), owned_(owned), size_(owned + (Ghost == na ? 0 : ghosts)), name_(name) {}

  /// Entity i of the span [0, size()) (local index: owned first, then ghosts).
  KOKKOS_INLINE_FUNCTION element& operator()(std::size_t i) const {
    static_assert(Owned != na || Ghost != na, "accessor<na, na> reaches no entity");
    if constexpr (Owned == na) {  // the index decides the region: always checked
      if (i < owned_) fail(i);
    }
#ifndef NDEBUG
    if (i >= size_) fail(i);
#endif
    return view_(i);
  }
  KOKKOS_INLINE_FUNCTION element& operator[](std::size_t i) const { return (*this)(i); }
  /// Owned entity i < owned_size(), writable when the owned privilege writes.
  KOKKOS_INLINE_FUNCTION owned_element& owned(std::size_t i) const {
    static_assert(Owned != na, "the owned privilege is na: owned values are out of reach");
#ifndef NDEBUG
    if (i >= owned_) fail(i);
#endif
    return view_(i);
  }
  /// Ghost entity j < ghost_size() (local index owned_size() + j), writable when the ghost
  /// privilege writes.
  KOKKOS_INLINE_FUNCTION ghost_element& ghost(std::size_t j) const {
    static_assert(Ghost != na, "the ghost privilege is na: ghost values are out of reach");
#ifndef NDEBUG
    if (owned_ + j >= size_) fail(owned_ + j);
#endif
    return view_(owned_ + j);
  }
  KOKKOS_INLINE_FUNCTION std::size_t owned_size() const { return owned_; }
  KOKKOS_INLINE_FUNCTION std::size_t ghost_size() const { return size_ - owned_; }
  /// Entities this accessor may touch (owned, plus ghosts unless the ghost privilege is na).
  KOKKOS_INLINE_FUNCTION std::size_t size() const { return size_; }
  /// The span's values in one array (owned first): not for an accessor whose owned privilege is na.
  element* data() const {
    static_assert(Owned != na, "the owned privilege is na: data() would expose the owned values");
    return view_.data();
  }
  /// The field's name (for messages), when the accessor was made from a field.
  const std::string* name() const { return name_; }

 private:
  [[noreturn]] void fail(std::size_t i) const {
    data::detail::access_outside_privileges(name_, i, owned_, size_, Owned, Ghost);
  }

  view_type view_;
  std::size_t owned_ = 0, size_ = 0;
  const std::string* name_ = nullptr;
};

/// A field bound to one topology instance; what execute() takes as an argument.
template<class T, class Topo>
class field_reference {
 public:
  using value_type = T;
  using topology_type = Topo;
  field_reference(Topo& topology, std::size_t id) : topology_(&topology), id_(id) {}

  /// This field, or no field when `present` is false: a task then gets an empty accessor (size 0,
  /// data() null), the launch has no access to the field, and no storage is ever made for it. For
  /// a field that only some physics reads and writes (an option that is off takes no memory).
  field_reference only_if(bool present) const {
    field_reference same = *this;
    same.present_ = present;
    return same;
  }
  /// False for an absent field (only_if(false)).
  bool present() const { return present_; }

  Topo& topology() const { return *topology_; }
  std::size_t id() const { return id_; }
  const std::string& name() const { return data::registered_fields<Topo>()[id_].name; }
  data::field_storage<T>& storage() const {
    if (!present_) throw std::logic_error("field '" + name() + "' is absent (only_if(false)): it has no storage");
    return topology_->template storage<T>(id_, name());
  }

  template<privilege Owned, privilege Ghost>
  accessor<T, Owned, Ghost> make_accessor() const {
    if (!present_) return {};
    auto& values = storage();
    return {values.view(), topology_->owned_size(), topology_->ghost_size(), &values.name()};
  }

 private:
  Topo* topology_;
  std::size_t id_;
  bool present_ = true;
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

}  // namespace flecsi_lite
