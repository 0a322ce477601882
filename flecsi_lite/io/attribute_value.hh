// The value of an HDF5 attribute in the I/O layer: a 64-bit integer, a double or a string, with
// checked conversion to the type a caller asks for.
#pragma once

#include "flecsi_lite/io/io_error.hh"

#include <cstdint>
#include <limits>
#include <string>
#include <type_traits>
#include <variant>

namespace flecsi_lite::io {

using attribute_value = std::variant<std::int64_t, double, std::string>;

/// "integer", "real" or "string".
inline const char* attribute_kind(const attribute_value& value) {
  static const char* const names[] = {"integer", "real", "string"};
  return names[value.index()];
}

/// The value as text; reals with enough digits to be read back exactly.
std::string to_string(const attribute_value& value);

/// The value as T: an integral type from an integer, a floating type from a real (or an integer,
/// which converts exactly below 2^53), std::string from a string. Throws element_type_error
/// naming `what` (e.g. "attribute 'dt' of step 3 in 'run.h5part'") otherwise.
template<class T>
T attribute_as(const attribute_value& value, const std::string& what) {
  const auto mismatch = [&](const char* wanted) {
    return element_type_error(what + " is " + attribute_kind(value) + " " + to_string(value) + ", not " + wanted);
  };
  if constexpr (std::is_same_v<T, std::string>) {
    if (auto* s = std::get_if<std::string>(&value)) return *s;
    throw mismatch("a string");
  } else if constexpr (std::is_floating_point_v<T>) {
    if (auto* d = std::get_if<double>(&value)) return static_cast<T>(*d);
    if (auto* i = std::get_if<std::int64_t>(&value)) return static_cast<T>(*i);
    throw mismatch("a real");
  } else {
    static_assert(std::is_integral_v<T>, "attributes convert to integers, reals or strings");
    if (auto* i = std::get_if<std::int64_t>(&value)) {
      const bool fits =
        std::is_signed_v<T>
          ? *i >= static_cast<std::int64_t>(std::numeric_limits<T>::min()) &&
              static_cast<std::uint64_t>(*i) <= static_cast<std::uint64_t>(std::numeric_limits<T>::max())
          : *i >= 0 && static_cast<std::uint64_t>(*i) <= std::numeric_limits<T>::max();
      if (fits) return static_cast<T>(*i);
      throw element_type_error(what + " = " + std::to_string(*i) + " does not fit the integer type asked for");
    }
    throw mismatch("an integer");
  }
}

}  // namespace flecsi_lite::io
