// Fields in H5Part files by their persistence: the walk over a topology's registered fields that
// writes and reads them (field_io.hh), with the values checked on every rank alike.
#include "flecsi_lite/io/field_io.hh"

#include "flecsi_lite/execution/executor.hh"
#include "flecsi_lite/io/collective_agreement.hh"

#include <optional>
#include <sstream>
#include <stdexcept>
#include <variant>

namespace flecsi_lite::data {
namespace {
/// Throws (on this rank) when some value breaks `rule`: "<where>: particle <i> has <name> = <v> (<rule>)".
void check_values(const std::vector<double>& values, const std::string& where, const std::string& name,
                  std::uint64_t first_index, const value_rule& rule) {
  for (std::size_t i = 0; i < values.size(); ++i) {
    if (rule.holds(values[i])) continue;
    std::ostringstream message;
    message << where << ": particle " << first_index + i << " has " << name << " = " << values[i] << " ("
            << rule.expectation << ")";
    throw std::invalid_argument(message.str());
  }
}

/// One component of one field to read: its dataset's values, unless the dataset is absent.
struct component_read {
  std::size_t field;
  int component;
  std::optional<value_buffer> values;
};
}  // namespace

std::string describe_step(const io::h5part_reader& in, std::int64_t step) {
  return "'" + in.path() + "' Step#" + std::to_string(step);
}

void write_registered_fields(topology_base& topology, const std::vector<registered_field>& fields,
                             io::h5part_writer& out, role roles) {
  execution::executor::instance().wait_all();
  const std::size_t n = topology.owned_size();
  for (std::size_t id = 0; id < fields.size(); ++id) {
    const registered_field& f = fields[id];
    if (!f.persistence.has(roles)) continue;
    const int written = f.persistence.is_padded() ? static_cast<int>(f.datasets.size()) : f.components;
    for (int k = 0; k < written; ++k) {
      value_buffer values = f.no_values();
      if (k < f.components)
        values = f.owned_values(topology, id, f.name, k);
      else
        std::visit([n](auto& zeros) { zeros.assign(n, 0); }, values);
      std::visit([&](const auto& v) { out.write(f.datasets[k], v.data(), v.size()); }, values);
    }
  }
}

void read_registered_fields(topology_base& topology, const std::vector<registered_field>& fields,
                            const io::h5part_reader& in, std::int64_t step, role which) {
  read_registered_fields(topology, fields, io::h5part_step_columns(in, step), which);
}

void read_registered_fields(topology_base& topology, const std::vector<registered_field>& fields,
                            const io::column_source& in, role which) {
  if (which != role::initial && which != role::restart)
    throw std::logic_error("fields are read as role::initial or role::restart data");
  const io::slice block = in.block();
  if (topology.owned_size() != block.count)
    throw std::logic_error("reading " + std::to_string(block.count) + " entities into " +
                           std::to_string(topology.owned_size()) + " owned ones");
  // Every dataset first (collective reads, the same on every rank), then the checks, then the fields.
  std::vector<component_read> reads;
  for (std::size_t id = 0; id < fields.size(); ++id) {
    const registered_field& f = fields[id];
    if (!f.persistence.has(which)) continue;
    const bool required = which == role::restart || f.persistence.reading() == initial_reading::required;
    for (int k = 0; k < f.components; ++k) {
      const std::string& name = f.datasets[k];
      component_read r{id, k, std::nullopt};
      if (required || in.has_column(name)) {
        // Checked values are read as reals, as the rule sees them; the others in their own type.
        if (f.persistence.rule())
          r.values = read_converted<double>(in, name);
        else
          r.values = std::visit(
            [&](const auto& empty) -> value_buffer {
              return read_converted<typename std::decay_t<decltype(empty)>::value_type>(in, name);
            },
            f.no_values());
      }
      reads.push_back(std::move(r));
    }
  }
  const std::string where = in.where();
  io::agree(in.communicator(), [&] {
    for (const component_read& r : reads) {
      const registered_field& f = fields[r.field];
      if (f.persistence.rule() && r.values)
        check_values(std::get<std::vector<double>>(*r.values), where, f.datasets[r.component], block.offset,
                     f.persistence.rule());
    }
  });
  execution::executor::instance().wait_all();
  for (component_read& r : reads) {
    const registered_field& f = fields[r.field];
    if (!r.values) {
      if (f.persistence.reading() == initial_reading::optional_index) {
        std::vector<std::uint64_t> index(block.count);
        for (std::size_t i = 0; i < block.count; ++i) index[i] = block.offset + i;
        r.values = std::move(index);
      } else {
        r.values = std::vector<double>(block.count, 0.0);
      }
    }
    f.assign_owned(topology, r.field, f.name, r.component, *r.values);
  }
}

}  // namespace flecsi_lite::data
