// Resolution of a parameter set (parameters.hh): defaults, then the `key = value` lines of a file
// read by rank 0 and broadcast, then command-line overrides; typed values with their origins.
#include "flecsi_lite/runtime/parameters.hh"

#include "flecsi_lite/runtime/parameter_text.hh"
#include "flecsi_lite/util/edit_distance.hh"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace flecsi_lite::runtime {

using detail::excerpt;
using detail::is_key;
using detail::strip_comment;
using detail::trim;

// ---- resolution ---------------------------------------------------------------------------

parameters parameters::parse(const parameter_schema& schema, const std::string& text, const std::string& source,
                             const std::vector<std::string>& overrides) {
  parameters result(schema);
  const std::string origin_of_file = source.empty() ? "parameter text" : source;
  for (const auto& d : schema.declarations()) {
    if (d.required()) continue;
    if (const auto problem = d.violation(*d.fallback()); !problem.empty())
      throw std::logic_error("parameter schema: the default of '" + d.name() + "' is invalid: " + problem);
    result.values_[d.name()] = {*d.fallback(), "default"};
  }
  const auto unknown_key = [&](const std::string& where, const std::string& key) {
    std::string message = where + ": unknown key '" + key + "'";
    if (const auto near = util::nearest_name(key, schema.names()); !near.empty())
      message += "; did you mean '" + near + "'?";
    return parameter_error(message);
  };
  // What every assignment, in the file or on the command line, must be before its key is looked up.
  const auto check_assignment = [](const std::string& where, const std::string& key, const std::string& value) {
    if (key.size() > detail::longest_key)
      throw parameter_error(where + ": key '" + excerpt(key) + "' is longer than " +
                            std::to_string(detail::longest_key) + " characters");
    if (!value.empty() && value.front() == '=')
      throw parameter_error(where + ": the value of key '" + key + "' starts with '=' ('" + excerpt(value) +
                            "'): write one '=' between key and value");
  };

  std::map<std::string, int> first_line;
  int number = 0;
  for (const std::string& raw : detail::split_lines(text)) {
    ++number;
    const std::string where = origin_of_file + ":" + std::to_string(number);
    const std::string line = trim(strip_comment(raw));
    if (line.empty()) continue;
    const auto equals = line.find('=');
    const std::string key = equals == std::string::npos ? "" : trim(line.substr(0, equals));
    const std::string value = equals == std::string::npos ? "" : trim(line.substr(equals + 1));
    check_assignment(where, key, value);
    if (!is_key(key))
      throw parameter_error(where + ": malformed line '" + excerpt(trim(raw)) + "' (expected 'key = value')");
    const parameter_declaration* declaration = schema.find(key);
    if (!declaration) throw unknown_key(where, key);
    if (auto first = first_line.find(key); first != first_line.end())
      throw parameter_error(where + ": key '" + key + "' is given twice (first on line " +
                            std::to_string(first->second) + ")");
    first_line[key] = number;
    if (value.empty()) throw parameter_error(where + ": key '" + key + "' has no value");
    std::string problem;
    const auto interpreted = declaration->interpret(value, problem);
    if (!interpreted)
      throw parameter_error(where + ": key '" + key + "' (" + parameter_type_name(declaration->type()) +
                            "): " + problem);
    result.values_[key] = {*interpreted, "file " + where};
  }

  for (const auto& assignment : overrides) {
    const std::string where = "command line (--set " + excerpt(assignment) + ")";
    const auto equals = assignment.find('=');
    const std::string key = equals == std::string::npos ? "" : trim(assignment.substr(0, equals));
    const std::string value = equals == std::string::npos ? "" : trim(assignment.substr(equals + 1));
    check_assignment(where, key, value);
    if (!is_key(key)) throw parameter_error(where + ": expected key=value");
    const parameter_declaration* declaration = schema.find(key);
    if (!declaration) throw unknown_key(where, key);
    if (value.empty()) throw parameter_error(where + ": key '" + key + "' has no value");
    std::string problem;
    const auto interpreted = declaration->interpret(value, problem);
    if (!interpreted)
      throw parameter_error(where + ": key '" + key + "' (" + parameter_type_name(declaration->type()) +
                            "): " + problem);
    result.values_[key] = {*interpreted, "command line"};
  }

  std::string missing;
  for (const auto& d : schema.declarations())
    if (!result.values_.count(d.name()))
      missing += (missing.empty() ? "'" : ", '") + d.name() + "' (" + d.description() + ")";
  if (!missing.empty())
    throw parameter_error(origin_of_file + ": missing required key " + missing +
                          "; give it in the parameter file or with --set key=value");

  result.sources_ = "defaults";
  if (!source.empty()) result.sources_ += ", then " + source;
  if (!overrides.empty()) result.sources_ += ", then the command line";
  return result;
}

namespace {
// Rank 0 reads the file; every rank receives its text or the reason it could not be read.
std::string read_on_root(const std::string& path, MPI_Comm comm) {
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  long long header[2] = {0, 0};  // {failed, size of the text or of the message}
  std::string text;
  if (rank == 0) {
    std::error_code error;
    std::ifstream in(path, std::ios::binary);
    if (std::filesystem::is_directory(path, error)) {
      header[0] = 1, text = "cannot read parameter file '" + path + "': it is a directory";
    } else if (!in) {
      header[0] = 1, text = "cannot read parameter file '" + path + "': " + std::strerror(errno);
    } else {
      std::ostringstream contents;
      contents << in.rdbuf();
      if (in.bad())
        header[0] = 1, text = "cannot read parameter file '" + path + "': read error";
      else
        text = contents.str();
    }
    header[1] = static_cast<long long>(text.size());
  }
  MPI_Bcast(header, 2, MPI_LONG_LONG, 0, comm);
  text.resize(static_cast<std::size_t>(header[1]));
  constexpr long long chunk = 1 << 30;
  for (long long done = 0; done < header[1]; done += chunk)
    MPI_Bcast(text.data() + done, static_cast<int>(std::min(chunk, header[1] - done)), MPI_CHAR, 0, comm);
  if (header[0]) throw parameter_error(text);
  return text;
}
}  // namespace

parameters parameters::load(const parameter_schema& schema, const std::string& path,
                            const std::vector<std::string>& overrides, MPI_Comm comm) {
  const std::string text = path.empty() ? std::string() : read_on_root(path, comm);
  return parse(schema, text, path, overrides);
}

const parameters::entry& parameters::lookup(const std::string& name, parameter_type wanted,
                                            const char* cxx_type) const {
  const parameter_declaration* declaration = schema_.find(name);
  if (!declaration) {
    std::string message = "parameters: no key '" + name + "' in the schema";
    if (const auto near = util::nearest_name(name, schema_.names()); !near.empty())
      message += "; did you mean '" + near + "'?";
    throw std::logic_error(message);
  }
  if (declaration->type() != wanted)
    throw std::logic_error("parameters: '" + name + "' is declared " + parameter_type_name(declaration->type()) +
                           " and cannot be read as " + cxx_type);
  return values_.at(name);
}

const parameter_value& parameters::value(const std::string& name) const {
  const parameter_declaration* declaration = schema_.find(name);
  return lookup(name, declaration ? declaration->type() : parameter_type::real, "").value;
}

const std::string& parameters::origin(const std::string& name) const {
  const parameter_declaration* declaration = schema_.find(name);
  return lookup(name, declaration ? declaration->type() : parameter_type::real, "").origin;
}

std::string parameters::resolved_text() const {
  std::vector<std::string> assignments;
  std::size_t width = 0;
  for (const auto& d : schema_.declarations()) {
    assignments.push_back(d.name() + " = " + parameter_declaration::format(values_.at(d.name()).value));
    width = std::max(width, assignments.back().size());
  }
  width = std::min<std::size_t>(width, 48);
  std::string text = "# resolved parameters (" + sources_ + ")\n";
  for (std::size_t i = 0; i < assignments.size(); ++i) {
    const std::string& name = schema_.declarations()[i].name();
    text += assignments[i] + std::string(width + 2 - std::min(width, assignments[i].size()), ' ') + "# " +
            values_.at(name).origin + "\n";
  }
  return text;
}

}  // namespace flecsi_lite::runtime
