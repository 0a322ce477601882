// One step of an H5Part file as particle columns (column_source.hh).
#include "flecsi_lite/io/column_source.hh"

#include "flecsi_lite/io/h5part_reader.hh"
#include "flecsi_lite/io/io_error.hh"

namespace flecsi_lite::io {

std::string h5part_step_columns::where() const { return "'" + in_.path() + "' Step#" + std::to_string(step_); }
MPI_Comm h5part_step_columns::communicator() const { return in_.communicator(); }
slice h5part_step_columns::block() const { return in_.block(step_); }
bool h5part_step_columns::has_column(const std::string& name) const { return in_.has_dataset(step_, name); }
element_type h5part_step_columns::column_type(const std::string& name) const { return in_.dataset_type(step_, name); }
void h5part_step_columns::read_column(const std::string& name, slice part, element_type type, void* out) const {
  switch (type) {
    case element_type::float64:
      return in_.read_into(step_, name, part, static_cast<double*>(out));
    case element_type::float32:
      return in_.read_into(step_, name, part, static_cast<float*>(out));
    case element_type::int64:
      return in_.read_into(step_, name, part, static_cast<std::int64_t*>(out));
    case element_type::uint64:
      return in_.read_into(step_, name, part, static_cast<std::uint64_t*>(out));
    case element_type::int32:
      return in_.read_into(step_, name, part, static_cast<std::int32_t*>(out));
    case element_type::unsupported:
      break;
  }
  throw element_type_error(where() + ": column '" + name + "' read as an unsupported type");
}

}  // namespace flecsi_lite::io
