// Internals of parameter files (parameters.hh): the text of a line (trimming, '#' comments, keys)
// and the locale-independent conversion of value text to each parameter type.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace flecsi_lite::runtime::detail {

std::string trim(const std::string& text);
/// Letters, digits, '_', '.' and '-', at least one.
bool is_key(const std::string& key);
/// The text up to the first '#' that is not inside a double-quoted string.
std::string strip_comment(const std::string& line);

// Each returns the value, or nullopt with `problem` saying what is wrong ("'abc' is not a real
// number"); reals and integers take an optional leading '+'.
std::optional<double> parse_real(const std::string& text, std::string& problem);
std::optional<std::int64_t> parse_integer(const std::string& text, std::string& problem);
/// true/false, yes/no, on/off, 1/0, in any case.
std::optional<bool> parse_boolean(const std::string& text, std::string& problem);
/// Plain text, or text in double quotes (which may then hold '#').
std::optional<std::string> parse_string(const std::string& text, std::string& problem);
/// "a, b, c", "a b c" or "[a, b]".
std::optional<std::vector<double>> parse_real_list(const std::string& text, std::string& problem);

/// The shortest text that reads back as exactly `value` (std::to_chars without a format).
std::string shortest_real(double value);

} // namespace flecsi_lite::runtime::detail
