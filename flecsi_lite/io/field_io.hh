// Fields in H5Part files by their persistence (data/persistence.hh): the owned values of every
// registered field with a role written into an open step, and read back from a step (this rank's
// balanced block, the seed's "read f in parallel"), converted from any numeric type and checked.
//
//   data::write_fields(particles, writer, data::role::output);                 // an output step
//   data::write_fields(particles, writer, data::role::output | data::role::restart);  // checkpoint
//   data::read_fields(particles, reader, step, data::role::initial);           // initial data
//   data::read_fields(particles, columns, data::role::initial);  // any io::column_source
#pragma once

#include "flecsi_lite/data/field_registry.hh"
#include "flecsi_lite/data/persistence.hh"
#include "flecsi_lite/data/topology_base.hh"
#include "flecsi_lite/io/column_source.hh"
#include "flecsi_lite/io/element_type.hh"
#include "flecsi_lite/io/h5part_reader.hh"
#include "flecsi_lite/io/h5part_writer.hh"
#include "flecsi_lite/io/io_error.hh"

#include <cstdint>
#include <string>
#include <vector>

namespace flecsi_lite::data {

/// "'path' Step#12" for messages: H5Part step `step` of the reader's file.
std::string describe_step(const io::h5part_reader& in, std::int64_t step);

/// This rank's block of column `name` as T, from any numeric element type of the file (users'
/// files may hold float32 positions or int32 ids); element_type_error for other types.
template<class T>
std::vector<T> read_converted(const io::column_source& in, const std::string& name) {
  const auto convert = [](const auto& values) { return std::vector<T>(values.begin(), values.end()); };
  switch (in.column_type(name)) {
    case io::element_type::float64:
      return convert(in.read<double>(name));
    case io::element_type::float32:
      return convert(in.read<float>(name));
    case io::element_type::int64:
      return convert(in.read<std::int64_t>(name));
    case io::element_type::uint64:
      return convert(in.read<std::uint64_t>(name));
    case io::element_type::int32:
      return convert(in.read<std::int32_t>(name));
    default:
      break;
  }
  throw io::element_type_error(in.where() + " dataset '" + name +
                               "' is not numeric (float64, float32, int64, uint64 or int32)");
}

/// Collective: writes into the open step of `out` the owned values of every field of `fields`
/// (the registry of `topology`'s type) that has any of `roles`, component by component under its
/// dataset names (zeros beyond the components of a padded field), each in its element type.
/// Waits for every pending task first.
void write_registered_fields(topology_base& topology, const std::vector<registered_field>& fields,
                             io::h5part_writer& out, role roles);

/// Collective: assigns the owned entities of `topology` (as many as the block of `in`) every
/// field of `fields` with role `which`, read from the columns of `in` (one H5Part step, ...):
///   role::initial  as each field's initial reading says (required, or absent: zero / index);
///   role::restart  every component required.
/// Values that break a field's rule throw std::invalid_argument (on every rank alike) naming the
/// file, the step, the dataset and the first bad entity; reading errors are io_errors. Waits for
/// every pending task before assigning.
void read_registered_fields(topology_base& topology, const std::vector<registered_field>& fields,
                            const io::column_source& in, role which);
/// The same from step `step` of an H5Part file.
void read_registered_fields(topology_base& topology, const std::vector<registered_field>& fields,
                            const io::h5part_reader& in, std::int64_t step, role which);

/// The same for the registry of Topo.
template<class Topo>
void write_fields(Topo& topology, io::h5part_writer& out, role roles) {
  write_registered_fields(topology, registered_fields<Topo>(), out, roles);
}
template<class Topo>
void read_fields(Topo& topology, const io::h5part_reader& in, std::int64_t step, role which) {
  read_registered_fields(topology, registered_fields<Topo>(), in, step, which);
}
template<class Topo>
void read_fields(Topo& topology, const io::column_source& in, role which) {
  read_registered_fields(topology, registered_fields<Topo>(), in, which);
}

}  // namespace flecsi_lite::data
