// Element types of per-particle arrays and their HDF5 counterparts: the type a C++ value maps to,
// the little-endian type stored in the file, the native type used in memory, and back.
#pragma once

#include <hdf5.h>

#include <string>
#include <type_traits>

namespace flecsi_lite::io {

enum class element_type { float64, float32, int64, uint64, int32, unsupported };

/// The element type of C++ type T (double, float, 64-bit signed or unsigned, 32-bit signed).
template<class T>
constexpr element_type element_type_of() {
  using U = std::remove_cv_t<T>;
  static_assert(!std::is_same_v<U, bool>, "store flags as int32");
  if constexpr (std::is_floating_point_v<U> && sizeof(U) == 8)
    return element_type::float64;
  else if constexpr (std::is_floating_point_v<U> && sizeof(U) == 4)
    return element_type::float32;
  else if constexpr (std::is_integral_v<U> && std::is_signed_v<U> && sizeof(U) == 8)
    return element_type::int64;
  else if constexpr (std::is_integral_v<U> && std::is_unsigned_v<U> && sizeof(U) == 8)
    return element_type::uint64;
  else if constexpr (std::is_integral_v<U> && std::is_signed_v<U> && sizeof(U) == 4)
    return element_type::int32;
  else {
    static_assert(sizeof(U) == 0, "H5Part arrays hold double, float, int64, uint64 or int32");
    return element_type::unsupported;
  }
}

/// "double", "float", "int64", "uint64", "int32" or "unsupported".
const char* element_type_name(element_type type);

/// The type HDF5 stores in the file (little-endian IEEE or two's complement).
hid_t file_type(element_type type);

/// The type of the values in this process's memory.
hid_t memory_type(element_type type);

/// The element type of an HDF5 datatype (any byte order); unsupported for other classes/sizes.
element_type classify(hid_t datatype);

/// A description of an HDF5 datatype for messages, e.g. "int16" or "string".
std::string describe_datatype(hid_t datatype);

}  // namespace flecsi_lite::io
