// Scalar HDF5 attributes (see hdf5_attributes.hh).
#include "flecsi_lite/io/detail/hdf5_attributes.hh"

#include "flecsi_lite/io/detail/hdf5_errors.hh"
#include "flecsi_lite/io/detail/hdf5_handle.hh"
#include "flecsi_lite/io/detail/hdf5_storage.hh"
#include "flecsi_lite/io/element_type.hh"

#include <vector>

namespace flecsi_lite::io {

namespace {
[[noreturn]] void fail(const std::string& message) { throw io_error(failure::system, message + hdf5_reason()); }
}  // namespace

void write_attribute(hid_t location, const std::string& name, const attribute_value& value) {
  if (has_attribute(location, name) && H5Adelete(location, name.c_str()) < 0)
    fail("cannot replace attribute '" + name + "'");
  auto space = dataspace_handle(H5Screate(H5S_SCALAR));
  hdf5_handle type;
  hid_t stored = H5I_INVALID_HID, in_memory = H5I_INVALID_HID;
  const void* data = nullptr;
  if (auto* i = std::get_if<std::int64_t>(&value)) {
    stored = H5T_STD_I64LE, in_memory = H5T_NATIVE_INT64, data = i;
  } else if (auto* d = std::get_if<double>(&value)) {
    stored = H5T_IEEE_F64LE, in_memory = H5T_NATIVE_DOUBLE, data = d;
  } else {
    const std::string& text = std::get<std::string>(value);
    type = datatype_handle(H5Tcopy(H5T_C_S1));
    if (!type || H5Tset_size(type.get(), text.size() + 1) < 0 || H5Tset_strpad(type.get(), H5T_STR_NULLTERM) < 0)
      fail("cannot make a string type for attribute '" + name + "'");
    stored = in_memory = type.get(), data = text.c_str();
  }
  auto attribute = attribute_handle(H5Acreate2(location, name.c_str(), stored, space.get(), H5P_DEFAULT, H5P_DEFAULT));
  if (!attribute || H5Awrite(attribute.get(), in_memory, data) < 0) fail("cannot write attribute '" + name + "'");
}

attribute_value read_attribute(hid_t location, const std::string& name, const std::string& what) {
  auto attribute = attribute_handle(H5Aopen(location, name.c_str(), H5P_DEFAULT));
  if (!attribute) fail("cannot open " + what);
  auto space = dataspace_handle(H5Aget_space(attribute.get()));
  auto type = datatype_handle(H5Aget_type(attribute.get()));
  if (!space || !type) fail("cannot inspect " + what);
  if (H5Sget_simple_extent_npoints(space.get()) != 1)
    throw element_type_error(what + " holds " + std::to_string(H5Sget_simple_extent_npoints(space.get())) +
                             " values; only single values are read");
  switch (H5Tget_class(type.get())) {
    case H5T_INTEGER: {
      std::int64_t v = 0;
      if (H5Aread(attribute.get(), H5T_NATIVE_INT64, &v) < 0) fail("cannot read " + what);
      return v;
    }
    case H5T_FLOAT: {
      double v = 0;
      if (H5Aread(attribute.get(), H5T_NATIVE_DOUBLE, &v) < 0) fail("cannot read " + what);
      return v;
    }
    case H5T_STRING: {
      if (H5Tis_variable_str(type.get()) > 0) {
        auto memory = datatype_handle(H5Tcopy(H5T_C_S1));
        H5Tset_size(memory.get(), H5T_VARIABLE);
        // In the file's character set: HDF5 converts no UTF-8 string (h5py's str) to ASCII.
        H5Tset_cset(memory.get(), H5Tget_cset(type.get()));
        char* text = nullptr;
        if (H5Aread(attribute.get(), memory.get(), &text) < 0) fail("cannot read " + what);
        std::string result = text ? text : "";
        H5free_memory(text);
        return result;
      }
      const std::size_t size = H5Tget_size(type.get());
      // A corrupted datatype may declare gigabytes: no larger than the file before allocating.
      if (const std::uint64_t file_size = file_size_of(attribute.get()); file_size > 0 && size > file_size)
        throw file_error(what + " declares a string of " + std::to_string(size) + " bytes in a file of " +
                         std::to_string(file_size) + " bytes: the file is corrupted");
      std::vector<char> buffer(size + 1, '\0');
      if (H5Aread(attribute.get(), type.get(), buffer.data()) < 0) fail("cannot read " + what);
      return std::string(buffer.data());  // stops at the terminator or the padding
    }
    default:
      throw element_type_error(what + " holds " + describe_datatype(type.get()) +
                               " values; only integers, reals and strings are read");
  }
}

bool has_attribute(hid_t location, const std::string& name) { return H5Aexists(location, name.c_str()) > 0; }

namespace {
herr_t collect_name(hid_t, const char* name, const H5A_info_t*, void* names) {
  static_cast<std::vector<std::string>*>(names)->emplace_back(name);
  return 0;
}
}  // namespace

std::vector<std::string> attribute_names(hid_t location) {
  std::vector<std::string> names;
  hsize_t index = 0;
  if (H5Aiterate2(location, H5_INDEX_NAME, H5_ITER_INC, &index, collect_name, &names) < 0)
    fail("cannot list attributes");
  return names;
}

}  // namespace flecsi_lite::io
