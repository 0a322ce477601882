// Parameter files: schema, parsing of `key = value` text and command-line overrides, typed
// values with their origins (see parameters.hh).
#include "flecsi_lite/runtime/parameters.hh"

#include "flecsi_lite/util/edit_distance.hh"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace flecsi_lite::runtime {

const char* parameter_type_name(parameter_type type) {
  switch (type) {
    case parameter_type::real: return "real";
    case parameter_type::integer: return "integer";
    case parameter_type::boolean: return "boolean";
    case parameter_type::string: return "string";
    case parameter_type::real_list: return "list of reals";
  }
  return "unknown";
}

namespace {
std::string trim(const std::string& text) {
  const auto first = text.find_first_not_of(" \t\r\n\f\v");
  if (first == std::string::npos) return "";
  return text.substr(first, text.find_last_not_of(" \t\r\n\f\v") - first + 1);
}

bool is_key(const std::string& key) {
  return !key.empty() && std::all_of(key.begin(), key.end(), [](char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.' || c == '-';
  });
}

// Text up to the first '#' that is not inside a double-quoted string.
std::string strip_comment(const std::string& line) {
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    if (line[i] == '"') quoted = !quoted;
    else if (line[i] == '#' && !quoted) return line.substr(0, i);
  }
  return line;
}

// from_chars is locale-independent and must consume the whole text; it takes no leading '+'.
std::string_view without_plus(const std::string& text) {
  std::string_view view = text;
  if (view.size() > 1 && view[0] == '+' && view[1] != '-' && view[1] != '+') view.remove_prefix(1);
  return view;
}

std::optional<double> parse_real(const std::string& text, std::string& problem) {
  const std::string_view view = without_plus(text);
  double value = 0;
  const auto [end, error] = std::from_chars(view.data(), view.data() + view.size(), value);
  if (error == std::errc::result_out_of_range && end == view.data() + view.size()) {
    problem = "'" + text + "' is out of the range of a double";
    return std::nullopt;
  }
  if (error != std::errc() || end != view.data() + view.size() || !std::isfinite(value)) {
    problem = "'" + text + "' is not a real number";
    return std::nullopt;
  }
  return value;
}

std::optional<std::int64_t> parse_integer(const std::string& text, std::string& problem) {
  const std::string_view view = without_plus(text);
  std::int64_t value = 0;
  const auto [end, error] = std::from_chars(view.data(), view.data() + view.size(), value);
  if (error == std::errc::result_out_of_range && end == view.data() + view.size()) {
    problem = "'" + text + "' is out of the range of a 64-bit integer";
    return std::nullopt;
  }
  if (error != std::errc() || end != view.data() + view.size()) {
    problem = "'" + text + "' is not an integer";
    return std::nullopt;
  }
  return value;
}

std::optional<bool> parse_boolean(const std::string& text, std::string& problem) {
  std::string lower = text;
  std::transform(lower.begin(), lower.end(), lower.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (lower == "true" || lower == "yes" || lower == "on" || lower == "1") return true;
  if (lower == "false" || lower == "no" || lower == "off" || lower == "0") return false;
  problem = "'" + text + "' is not a boolean (use true/false, yes/no, on/off or 1/0)";
  return std::nullopt;
}

std::optional<std::string> parse_string(const std::string& text, std::string& problem) {
  const auto quotes = std::count(text.begin(), text.end(), '"');
  if (quotes == 0) return text;
  if (quotes == 2 && text.size() >= 2 && text.front() == '"' && text.back() == '"')
    return text.substr(1, text.size() - 2);
  problem = "'" + text + "' is not a string (quote it as \"...\"; strings cannot contain '\"')";
  return std::nullopt;
}

std::optional<std::vector<double>> parse_real_list(const std::string& text, std::string& problem) {
  std::string body = text;
  if (body.size() >= 2 && body.front() == '[' && body.back() == ']') body = trim(body.substr(1, body.size() - 2));
  std::vector<std::string> items;
  if (body.find(',') != std::string::npos) {
    std::stringstream in(body);
    for (std::string item; std::getline(in, item, ',');) items.push_back(trim(item));
    if (body.back() == ',') items.emplace_back();
  } else {
    std::istringstream in(body);
    for (std::string item; in >> item;) items.push_back(item);
  }
  std::vector<double> values;
  for (std::size_t i = 0; i < items.size(); ++i) {
    std::string element_problem;
    const auto value = items[i].empty() ? std::nullopt : parse_real(items[i], element_problem);
    if (!value) {
      problem = "'" + text + "' is not a list of reals (element " + std::to_string(i + 1) + " '" +
                items[i] + "' is not a real number)";
      return std::nullopt;
    }
    values.push_back(*value);
  }
  return values;
}

// The shortest text that reads back as exactly `value` (std::to_chars without a format).
std::string shortest_real(double value) {
  char text[32];
  const auto result = std::to_chars(text, text + sizeof text, value);
  return std::string(text, result.ptr);
}
} // namespace

// ---- declarations -------------------------------------------------------------------------

parameter_declaration::parameter_declaration(std::string name, parameter_type type, std::string description)
  : name_(std::move(name)), type_(type), description_(std::move(description)) {}

parameter_declaration& parameter_declaration::set_default(parameter_value value) {
  // The variant's alternatives follow the order of parameter_type.
  if (value.index() != static_cast<std::size_t>(type_))
    throw std::logic_error("parameter schema: the default of '" + name_ + "' is not a " +
                           parameter_type_name(type_));
  default_ = std::move(value);
  return *this;
}

namespace {
void require_bounded_type(parameter_type type, const std::string& name) {
  if (type != parameter_type::real && type != parameter_type::integer && type != parameter_type::real_list)
    throw std::logic_error("parameter schema: '" + name + "' is a " + parameter_type_name(type) +
                           " and cannot have bounds");
}
} // namespace

parameter_declaration& parameter_declaration::at_least(double minimum) {
  require_bounded_type(type_, name_);
  lower_ = bound{minimum, true};
  return *this;
}
parameter_declaration& parameter_declaration::greater_than(double minimum) {
  require_bounded_type(type_, name_);
  lower_ = bound{minimum, false};
  return *this;
}
parameter_declaration& parameter_declaration::at_most(double maximum) {
  require_bounded_type(type_, name_);
  upper_ = bound{maximum, true};
  return *this;
}
parameter_declaration& parameter_declaration::less_than(double maximum) {
  require_bounded_type(type_, name_);
  upper_ = bound{maximum, false};
  return *this;
}
parameter_declaration& parameter_declaration::length(std::size_t count) {
  if (type_ != parameter_type::real_list)
    throw std::logic_error("parameter schema: '" + name_ + "' is not a list and cannot have a length");
  length_ = count;
  return *this;
}

std::string parameter_declaration::bounds_text() const {
  if (lower_ && upper_)
    return std::string("in ") + (lower_->inclusive ? "[" : "(") + shortest_real(lower_->value) + ", " +
           shortest_real(upper_->value) + (upper_->inclusive ? "]" : ")");
  if (lower_) return std::string(lower_->inclusive ? ">= " : "> ") + shortest_real(lower_->value);
  if (upper_) return std::string(upper_->inclusive ? "<= " : "< ") + shortest_real(upper_->value);
  return "";
}

std::string parameter_declaration::constraint_text() const {
  const std::string bounds = bounds_text();
  if (type_ == parameter_type::real_list) {
    std::string text = length_ ? std::to_string(*length_) + " elements" : "";
    if (!bounds.empty()) text += (text.empty() ? "elements " : " ") + bounds;
    return text;
  }
  if (!choices_.empty()) {
    std::string text = "one of:";
    for (std::size_t i = 0; i < choices_.size(); ++i) text += (i ? ", " : " ") + choices_[i];
    return text;
  }
  return bounds;
}

std::string parameter_declaration::violation(const parameter_value& value) const {
  const auto outside = [&](double v) {
    return (lower_ && (lower_->inclusive ? v < lower_->value : v <= lower_->value)) ||
           (upper_ && (upper_->inclusive ? v > upper_->value : v >= upper_->value));
  };
  switch (type_) {
    case parameter_type::real:
    case parameter_type::integer: {
      const double v = type_ == parameter_type::real ? std::get<double>(value)
                                                     : static_cast<double>(std::get<std::int64_t>(value));
      if (outside(v)) return format(value) + " is out of range (must be " + constraint_text() + ")";
      return "";
    }
    case parameter_type::real_list: {
      const auto& values = std::get<std::vector<double>>(value);
      if (length_ && values.size() != *length_)
        return format(value) + " has " + std::to_string(values.size()) + " elements, not " +
               std::to_string(*length_);
      for (std::size_t i = 0; i < values.size(); ++i)
        if (outside(values[i]))
          return "element " + std::to_string(i + 1) + " (" + shortest_real(values[i]) +
                 ") is out of range (must be " + bounds_text() + ")";
      return "";
    }
    case parameter_type::string: {
      const auto& text = std::get<std::string>(value);
      if (choices_.empty() || std::find(choices_.begin(), choices_.end(), text) != choices_.end()) return "";
      std::string message = "'" + text + "' is not " + constraint_text();
      if (const auto near = util::nearest_name(text, choices_); !near.empty())
        message += "; did you mean '" + near + "'?";
      return message;
    }
    case parameter_type::boolean: return "";
  }
  return "";
}

std::optional<parameter_value> parameter_declaration::interpret(const std::string& text,
                                                                std::string& problem) const {
  std::optional<parameter_value> value;
  switch (type_) {
    case parameter_type::real: if (auto v = parse_real(text, problem)) value = *v; break;
    case parameter_type::integer: if (auto v = parse_integer(text, problem)) value = *v; break;
    case parameter_type::boolean: if (auto v = parse_boolean(text, problem)) value = *v; break;
    case parameter_type::string: if (auto v = parse_string(text, problem)) value = *v; break;
    case parameter_type::real_list: if (auto v = parse_real_list(text, problem)) value = *v; break;
  }
  if (!value) return std::nullopt;
  problem = violation(*value);
  if (!problem.empty()) return std::nullopt;
  return value;
}

std::string parameter_declaration::format(const parameter_value& value) {
  struct formatter {
    std::string operator()(double v) const { return shortest_real(v); }
    std::string operator()(std::int64_t v) const { return std::to_string(v); }
    std::string operator()(bool v) const { return v ? "true" : "false"; }
    std::string operator()(const std::string& v) const { return '"' + v + '"'; }
    std::string operator()(const std::vector<double>& v) const {
      std::string text;
      for (std::size_t i = 0; i < v.size(); ++i) text += (i ? ", " : "") + shortest_real(v[i]);
      return text;
    }
  };
  return std::visit(formatter{}, value);
}

// ---- schema -------------------------------------------------------------------------------

parameter_declaration& parameter_schema::declare(const std::string& name, parameter_type type,
                                                 const std::string& description) {
  if (!is_key(name))
    throw std::logic_error("parameter schema: '" + name + "' is not a valid key (letters, digits, '_', '.', '-')");
  if (find(name)) throw std::logic_error("parameter schema: '" + name + "' is declared twice");
  return declarations_.emplace_back(name, type, description);
}

parameter_declaration& parameter_schema::real(const std::string& name, const std::string& description) {
  return declare(name, parameter_type::real, description);
}
parameter_declaration& parameter_schema::integer(const std::string& name, const std::string& description) {
  return declare(name, parameter_type::integer, description);
}
parameter_declaration& parameter_schema::boolean(const std::string& name, const std::string& description) {
  return declare(name, parameter_type::boolean, description);
}
parameter_declaration& parameter_schema::string(const std::string& name, const std::string& description) {
  return declare(name, parameter_type::string, description);
}
parameter_declaration& parameter_schema::choice(const std::string& name, std::vector<std::string> choices,
                                                const std::string& description) {
  if (choices.empty()) throw std::logic_error("parameter schema: '" + name + "' has no choices");
  auto& declaration = declare(name, parameter_type::string, description);
  declaration.choices_ = std::move(choices);
  return declaration;
}
parameter_declaration& parameter_schema::real_list(const std::string& name, const std::string& description) {
  return declare(name, parameter_type::real_list, description);
}

const parameter_declaration* parameter_schema::find(const std::string& name) const {
  for (const auto& declaration : declarations_)
    if (declaration.name() == name) return &declaration;
  return nullptr;
}

std::vector<std::string> parameter_schema::names() const {
  std::vector<std::string> result;
  for (const auto& declaration : declarations_) result.push_back(declaration.name());
  return result;
}

std::string parameter_schema::help() const {
  std::string text;
  for (const auto& d : declarations_) {
    text += "  " + d.name() + " (" + parameter_type_name(d.type());
    text += d.required() ? ", required" : ", default " + parameter_declaration::format(*d.fallback());
    if (const auto constraint = d.constraint_text(); !constraint.empty()) text += ", " + constraint;
    text += ")\n      " + d.description() + "\n";
  }
  return text;
}

// ---- resolution ---------------------------------------------------------------------------

parameters parameters::parse(const parameter_schema& schema, const std::string& text,
                             const std::string& source, const std::vector<std::string>& overrides) {
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

  std::map<std::string, int> first_line;
  std::istringstream lines(text);
  int number = 0;
  for (std::string raw; std::getline(lines, raw);) {
    ++number;
    const std::string where = origin_of_file + ":" + std::to_string(number);
    const std::string line = trim(strip_comment(raw));
    if (line.empty()) continue;
    const auto equals = line.find('=');
    const std::string key = equals == std::string::npos ? "" : trim(line.substr(0, equals));
    if (!is_key(key))
      throw parameter_error(where + ": malformed line '" + trim(raw) + "' (expected 'key = value')");
    const std::string value = trim(line.substr(equals + 1));
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
    const std::string where = "command line (--set " + assignment + ")";
    const auto equals = assignment.find('=');
    const std::string key = equals == std::string::npos ? "" : trim(assignment.substr(0, equals));
    if (!is_key(key)) throw parameter_error(where + ": expected key=value");
    const parameter_declaration* declaration = schema.find(key);
    if (!declaration) throw unknown_key(where, key);
    const std::string value = trim(assignment.substr(equals + 1));
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
      if (in.bad()) header[0] = 1, text = "cannot read parameter file '" + path + "': read error";
      else text = contents.str();
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
} // namespace

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
    text += assignments[i] + std::string(width + 2 - std::min(width, assignments[i].size()), ' ') +
            "# " + values_.at(name).origin + "\n";
  }
  return text;
}

} // namespace flecsi_lite::runtime
