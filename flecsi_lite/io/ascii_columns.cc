// ASCII column export of an H5Part step for splash (see ascii_columns.hh).
#include "flecsi_lite/io/ascii_columns.hh"

#include <algorithm>
#include <cstdio>
#include <variant>

namespace flecsi_lite::io {

namespace {
// Splash finds labels separated by several spaces; '=' and ',' would change how it splits them.
std::string label_of(std::string name) {
  for (char& c : name)
    if (c == ' ' || c == '=' || c == ',' || c == '\t') c = '_';
  return name;
}

using column = std::variant<std::vector<double>, std::vector<float>, std::vector<std::int64_t>,
                            std::vector<std::uint64_t>, std::vector<std::int32_t>>;

column read_column(const h5part_reader& reader, std::int64_t step, const std::string& name, slice all) {
  switch (reader.dataset_type(step, name)) {
    case element_type::float64:
      return reader.read<double>(step, name, all);
    case element_type::float32:
      return reader.read<float>(step, name, all);
    case element_type::int64:
      return reader.read<std::int64_t>(step, name, all);
    case element_type::uint64:
      return reader.read<std::uint64_t>(step, name, all);
    case element_type::int32:
      return reader.read<std::int32_t>(step, name, all);
    case element_type::unsupported:
      break;
  }
  throw element_type_error("dataset '" + name + "' of step " + std::to_string(step) + " of '" + reader.path() +
                           "' holds values that cannot be written as numbers");
}

// One field of width 24: a separating space and the value right-aligned in 23 characters.
void append_value(std::string& row, const column& values, std::size_t i) {
  char text[48];
  if (auto* d = std::get_if<std::vector<double>>(&values))
    std::snprintf(text, sizeof text, " %23.16e", (*d)[i]);
  else if (auto* f = std::get_if<std::vector<float>>(&values))
    std::snprintf(text, sizeof text, " %23.8e", static_cast<double>((*f)[i]));
  else if (auto* s = std::get_if<std::vector<std::int64_t>>(&values))
    std::snprintf(text, sizeof text, " %23lld", static_cast<long long>((*s)[i]));
  else if (auto* u = std::get_if<std::vector<std::uint64_t>>(&values))
    std::snprintf(text, sizeof text, " %23llu", static_cast<unsigned long long>((*u)[i]));
  else
    std::snprintf(text, sizeof text, " %23d", static_cast<int>(std::get<std::vector<std::int32_t>>(values)[i]));
  row += text;
}
}  // namespace

std::vector<std::string> available_columns(const h5part_reader& reader, std::int64_t step,
                                           const std::vector<std::string>& preferred) {
  const auto present = reader.datasets(step);
  std::vector<std::string> chosen;
  for (const auto& name : preferred)
    if (std::find(present.begin(), present.end(), name) != present.end()) chosen.push_back(name);
  return chosen.empty() ? present : chosen;
}

void write_ascii_columns(const h5part_reader& reader, std::int64_t step, const std::vector<std::string>& columns,
                         std::ostream& out) {
  const step_info info = reader.step_information(step);
  const slice all{0, reader.particle_count(step)};
  std::vector<column> values;
  for (const auto& name : columns) values.push_back(read_column(reader, step, name, all));

  // Splash takes the time from the first number of a header line that contains a '.'.
  char time[40];
  std::snprintf(time, sizeof time, "%.16e", info.time);
  out << "# " << time << "  is the time of Step#" << step << " (iteration " << info.step << ") in " << reader.path()
      << '\n';
  // Labels right-aligned over their columns (fields of 24 characters), at least 4 spaces apart.
  std::string labels;
  for (const auto& name : columns) {
    const std::string label = label_of(name);
    const std::size_t padding = label.size() < 20 ? 24 - label.size() : 4;
    labels += std::string(padding, ' ') + label;
  }
  if (labels.empty()) labels = " ";
  labels[0] = '#';
  out << labels << '\n';
  std::string row;
  for (std::uint64_t i = 0; i < all.count; ++i) {
    row.clear();
    for (const auto& v : values) append_value(row, v, i);
    out << row << '\n';
  }
}

}  // namespace flecsi_lite::io
