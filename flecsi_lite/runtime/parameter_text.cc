// Text of parameter files: trimming, comments, keys, and locale-independent conversion of value
// text to reals, integers, booleans, strings and lists of reals (parameter_text.hh).
#include "flecsi_lite/runtime/parameter_text.hh"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <sstream>

namespace flecsi_lite::runtime::detail {
std::vector<std::string> split_lines(const std::string& text) {
  std::vector<std::string> lines;
  std::size_t start = 0;
  for (std::size_t i = 0; i < text.size(); ++i) {
    if (text[i] != '\n' && text[i] != '\r') continue;
    lines.push_back(text.substr(start, i - start));
    if (text[i] == '\r' && i + 1 < text.size() && text[i + 1] == '\n') ++i;  // CRLF: one line end
    start = i + 1;
  }
  if (start < text.size()) lines.push_back(text.substr(start));
  return lines;
}

std::string excerpt(const std::string& text) {
  constexpr std::size_t shown = 60;
  if (text.size() <= shown + 20) return text;
  return text.substr(0, shown) + "... (" + std::to_string(text.size()) + " characters)";
}

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
    if (line[i] == '"')
      quoted = !quoted;
    else if (line[i] == '#' && !quoted)
      return line.substr(0, i);
  }
  return line;
}

namespace {
// from_chars is locale-independent and must consume the whole text; it takes no leading '+'.
std::string_view without_plus(const std::string& text) {
  std::string_view view = text;
  if (view.size() > 1 && view[0] == '+' && view[1] != '-' && view[1] != '+') view.remove_prefix(1);
  return view;
}
}  // namespace

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
      problem = "'" + text + "' is not a list of reals (element " + std::to_string(i + 1) + " '" + items[i] +
                "' is not a real number)";
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
}  // namespace flecsi_lite::runtime::detail
