// Mapping between element types and HDF5 datatypes (see element_type.hh).
#include "flecsi_lite/io/element_type.hh"

namespace flecsi_lite::io {

const char* element_type_name(element_type type) {
  switch (type) {
    case element_type::float64:
      return "double";
    case element_type::float32:
      return "float";
    case element_type::int64:
      return "int64";
    case element_type::uint64:
      return "uint64";
    case element_type::int32:
      return "int32";
    case element_type::unsupported:
      break;
  }
  return "unsupported";
}

hid_t file_type(element_type type) {
  switch (type) {
    case element_type::float64:
      return H5T_IEEE_F64LE;
    case element_type::float32:
      return H5T_IEEE_F32LE;
    case element_type::int64:
      return H5T_STD_I64LE;
    case element_type::uint64:
      return H5T_STD_U64LE;
    case element_type::int32:
      return H5T_STD_I32LE;
    case element_type::unsupported:
      break;
  }
  return H5I_INVALID_HID;
}

hid_t memory_type(element_type type) {
  switch (type) {
    case element_type::float64:
      return H5T_NATIVE_DOUBLE;
    case element_type::float32:
      return H5T_NATIVE_FLOAT;
    case element_type::int64:
      return H5T_NATIVE_INT64;
    case element_type::uint64:
      return H5T_NATIVE_UINT64;
    case element_type::int32:
      return H5T_NATIVE_INT32;
    case element_type::unsupported:
      break;
  }
  return H5I_INVALID_HID;
}

element_type classify(hid_t datatype) {
  const std::size_t size = H5Tget_size(datatype);
  switch (H5Tget_class(datatype)) {
    case H5T_FLOAT:
      if (size == 8) return element_type::float64;
      if (size == 4) return element_type::float32;
      break;
    case H5T_INTEGER: {
      const bool is_signed = H5Tget_sign(datatype) == H5T_SGN_2;
      if (size == 8) return is_signed ? element_type::int64 : element_type::uint64;
      if (size == 4 && is_signed) return element_type::int32;
      break;
    }
    default:
      break;
  }
  return element_type::unsupported;
}

std::string describe_datatype(hid_t datatype) {
  if (const element_type type = classify(datatype); type != element_type::unsupported) return element_type_name(type);
  const std::string bits = std::to_string(8 * H5Tget_size(datatype));
  switch (H5Tget_class(datatype)) {
    case H5T_INTEGER:
      return (H5Tget_sign(datatype) == H5T_SGN_2 ? "int" : "uint") + bits;
    case H5T_FLOAT:
      return "float" + bits;
    case H5T_STRING:
      return "string";
    case H5T_COMPOUND:
      return "compound";
    case H5T_ARRAY:
      return "array";
    default:
      return "non-numeric type";
  }
}

}  // namespace flecsi_lite::io
