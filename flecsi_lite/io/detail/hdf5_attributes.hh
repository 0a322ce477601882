// Scalar HDF5 attributes on a file, group or dataset: written (replacing any of the same name),
// read back as attribute_value, and listed by name.
#pragma once

#include "flecsi_lite/io/attribute_value.hh"

#include <hdf5.h>

#include <string>
#include <vector>

namespace flecsi_lite::io {

/// Writes (or replaces) attribute `name` on `location`: integers as int64, reals as double,
/// strings as null-terminated fixed-length ASCII. In parallel every rank calls it with the same
/// value. Throws io_error (failure::system) when HDF5 fails.
void write_attribute(hid_t location, const std::string& name, const attribute_value& value);

/// Reads the scalar attribute `name`: integers of any size as int64, floats as double, fixed or
/// variable-length strings as string. Throws element_type_error for other classes and for
/// non-scalar attributes, io_error when HDF5 fails; `what` names the place for messages.
attribute_value read_attribute(hid_t location, const std::string& name, const std::string& what);

bool has_attribute(hid_t location, const std::string& name);

/// The names of the attributes of `location`, in HDF5's name order.
std::vector<std::string> attribute_names(hid_t location);

}  // namespace flecsi_lite::io
