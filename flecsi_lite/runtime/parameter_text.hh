// Internals of parameter files (parameters.hh): the text of a line (trimming, '#' comments, keys)
// and the locale-independent conversion of value text to each parameter type.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace flecsi_lite::runtime::detail {

/// The longest key a parameter file may give: longer ones are an error before any lookup (and
/// before "did you mean", whose cost grows with the key's length).
inline constexpr std::size_t longest_key = 200;

/// The lines of `text`: each of LF, CRLF and a lone CR (old Mac files) ends a line, so that a file
/// saved with any of them has the same lines and line numbers; the line ends are not kept.
std::vector<std::string> split_lines(const std::string& text);
/// `text` itself when short, else its first characters, "..." and its length: long input quoted
/// in a message stays readable.
std::string excerpt(const std::string& text);

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

}  // namespace flecsi_lite::runtime::detail
