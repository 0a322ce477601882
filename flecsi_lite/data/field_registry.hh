// The registry of the fields defined on a topology type: per field its name, its persistence
// (data/persistence.hh) and type-erased copies of its owned values to and from plain buffers, so
// that the I/O can walk every field without knowing its type (FleCSI's field registration).
#pragma once

#include "flecsi_lite/data/persistence.hh"
#include "flecsi_lite/data/topology_base.hh"

#include <array>
#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

namespace flecsi_lite::data {

/// One component of the owned entities of a field, in the component's own element type (an enum
/// is stored as its underlying integer, so a 32-bit kind stays int32 in the files).
using value_buffer = std::variant<std::vector<double>, std::vector<float>, std::vector<std::int32_t>,
                                  std::vector<std::int64_t>, std::vector<std::uint64_t>>;

namespace detail {
/// The element type of one component of T, and the number of components: T itself (or its
/// underlying type for an enum) and 1; S and N for std::array<S, N>.
template<class T, class = void>
struct element_of {
  using type = T;
};
template<class T>
struct element_of<T, std::enable_if_t<std::is_enum_v<T>>> {
  using type = std::underlying_type_t<T>;
};
template<class T>
struct components_of {
  using element = typename element_of<T>::type;
  static constexpr int count = 1;
  static const T& get(const T& value, int) { return value; }
  static T& get(T& value, int) { return value; }
};
template<class S, std::size_t N>
struct components_of<std::array<S, N>> {
  using element = typename element_of<S>::type;
  static constexpr int count = static_cast<int>(N);
  static const S& get(const std::array<S, N>& value, int k) { return value[k]; }
  static S& get(std::array<S, N>& value, int k) { return value[k]; }
};

template<class T>
constexpr bool persistable() {
  using E = typename components_of<T>::element;
  return std::is_same_v<E, double> || std::is_same_v<E, float> || std::is_same_v<E, std::int32_t> ||
         std::is_same_v<E, std::int64_t> || std::is_same_v<E, std::uint64_t>;
}

template<class T>
value_buffer owned_values(topology_base& topology, std::size_t id, const std::string& name, int component) {
  using traits = components_of<T>;
  using E = typename traits::element;
  const auto view = topology.storage<T>(id, name).view();
  std::vector<E> values(topology.owned_size());
  for (std::size_t i = 0; i < values.size(); ++i) values[i] = static_cast<E>(traits::get(view(i), component));
  return values;
}

template<class T>
void assign_owned(topology_base& topology, std::size_t id, const std::string& name, int component,
                  const value_buffer& values) {
  using traits = components_of<T>;
  using S = std::remove_reference_t<decltype(traits::get(std::declval<T&>(), 0))>;
  const auto view = topology.storage<T>(id, name).view();
  std::visit(
    [&](const auto& source) {
      if (source.size() != topology.owned_size())
        throw std::logic_error("field '" + name + "': " + std::to_string(source.size()) + " values for " +
                               std::to_string(topology.owned_size()) + " owned entities");
      for (std::size_t i = 0; i < source.size(); ++i)
        traits::get(view(i), component) = static_cast<S>(static_cast<typename traits::element>(source[i]));
    },
    values);
}

template<class T>
value_buffer no_values() {
  return std::vector<typename components_of<T>::element>();
}
}  // namespace detail

/// A field as the registry of its topology type holds it.
struct registered_field {
  std::string name;
  data::persistence persistence;
  int components = 1;
  /// Dataset name of each component (and of the padding beyond them), resolved from persistence.
  std::vector<std::string> datasets;
  /// The owned values of one component; assigns them (converted to the component's type).
  value_buffer (*owned_values)(topology_base&, std::size_t id, const std::string& name, int component) = nullptr;
  void (*assign_owned)(topology_base&, std::size_t id, const std::string& name, int component,
                       const value_buffer&) = nullptr;
  /// An empty buffer of the components' element type (what a reader should convert to).
  value_buffer (*no_values)() = nullptr;
};

/// The fields defined on topology type Topo; a field's id is its index here.
template<class Topo>
std::vector<registered_field>& registered_fields() {
  static std::vector<registered_field> fields;
  return fields;
}

/// The registry entry of a field of type T; fields that persist must have numeric components.
template<class T>
registered_field make_registered_field(std::string name, data::persistence persistence) {
  registered_field f;
  f.components = detail::components_of<T>::count;
  f.datasets = persistence.dataset_names(name, f.components);
  if constexpr (detail::persistable<T>()) {
    f.owned_values = &detail::owned_values<T>;
    f.assign_owned = &detail::assign_owned<T>;
    f.no_values = &detail::no_values<T>;
  } else if (persistence.roles() != role::none) {
    throw std::logic_error("field '" + name + "' cannot persist: its components are not numeric");
  }
  if (int(f.datasets.size()) < f.components)
    throw std::logic_error("field '" + name + "' has " + std::to_string(f.components) + " components but " +
                           std::to_string(f.datasets.size()) + " dataset names");
  f.name = std::move(name);
  f.persistence = std::move(persistence);
  return f;
}

// The element types of most fields, compiled once in field_instances.cc.
extern template registered_field make_registered_field<double>(std::string, data::persistence);
extern template registered_field make_registered_field<std::uint64_t>(std::string, data::persistence);
extern template registered_field make_registered_field<std::int64_t>(std::string, data::persistence);
extern template registered_field make_registered_field<std::array<double, 1>>(std::string, data::persistence);
extern template registered_field make_registered_field<std::array<double, 2>>(std::string, data::persistence);
extern template registered_field make_registered_field<std::array<double, 3>>(std::string, data::persistence);

}  // namespace flecsi_lite::data
