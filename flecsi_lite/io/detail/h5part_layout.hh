// The H5Part file layout (Howison et al., "H5hut: a high-performance I/O library for particle-
// based simulations", 2010), as ParaView's H5PartReader reads it: a root group with one group per
// step, Step#0, Step#1, ..., each holding one 1-D dataset per quantity, all of one length.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace flecsi_lite::io::h5part {

inline constexpr std::string_view step_prefix = "Step#";

/// "Step#<index>".
inline std::string step_group_name(std::int64_t index) { return std::string(step_prefix) + std::to_string(index); }

/// The index of a step group name: "Step#12" -> 12. Empty for other names, for negative or
/// signed numbers and for leading zeros ("Step#01"), which H5Part never writes.
inline std::optional<std::int64_t> parse_step_group_name(std::string_view name) {
  if (name.substr(0, step_prefix.size()) != step_prefix) return std::nullopt;
  const std::string_view digits = name.substr(step_prefix.size());
  if (digits.empty() || digits.size() > 18 || (digits.size() > 1 && digits[0] == '0')) return std::nullopt;
  std::int64_t index = 0;
  for (char c : digits) {
    if (c < '0' || c > '9') return std::nullopt;
    index = 10 * index + (c - '0');
  }
  return index;
}

/// Attribute names. Per step: TimeValue is where ParaView's H5Part reader takes the time from;
/// time, step (the simulation's iteration number) and dt are for everyone else. At the root:
/// NumSteps (kept up to date as steps are written) and the description of the run.
namespace attribute {
inline constexpr const char* time_value = "TimeValue";
inline constexpr const char* time = "time";
inline constexpr const char* step = "step";
inline constexpr const char* dt = "dt";
inline constexpr const char* num_steps = "NumSteps";
inline constexpr const char* program = "program";
inline constexpr const char* parameters = "parameters";
inline constexpr const char* dimension = "dimension";
}  // namespace attribute

}  // namespace flecsi_lite::io::h5part
