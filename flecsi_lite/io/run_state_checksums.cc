// FNV-1a checksums of a checkpoint's run state (run_state_checksums.hh).
#include "flecsi_lite/io/run_state_checksums.hh"

#include <cstdio>
#include <cstring>
#include <set>
#include <sstream>

namespace flecsi_lite::io {

namespace {
// FNV-1a, 64 bits: offset basis and prime of draft-eastlake-fnv, section 2.
constexpr std::uint64_t fnv_offset = 14695981039346656037ull, fnv_prime = 1099511628211ull;

void mix(std::uint64_t& hash, unsigned char byte) {
  hash ^= byte;
  hash *= fnv_prime;
}

void mix_word(std::uint64_t& hash, std::uint64_t word) {
  for (int k = 0; k < 8; ++k) mix(hash, static_cast<unsigned char>(word >> (8 * k)));
}

std::string hex(std::uint64_t hash) {
  char text[17];
  std::snprintf(text, sizeof text, "%016llx", static_cast<unsigned long long>(hash));
  return text;
}
}  // namespace

std::uint64_t fnv1a(const attribute_value& value) {
  std::uint64_t hash = fnv_offset;
  mix(hash, static_cast<unsigned char>(value.index()));
  if (const auto* i = std::get_if<std::int64_t>(&value)) {
    mix_word(hash, static_cast<std::uint64_t>(*i));
  } else if (const auto* d = std::get_if<double>(&value)) {
    std::uint64_t bits = 0;
    std::memcpy(&bits, d, sizeof bits);  // the exact bits: -0, NaN payloads and ulps all count
    mix_word(hash, bits);
  } else {
    for (const char c : std::get<std::string>(value)) mix(hash, static_cast<unsigned char>(c));
  }
  return hash;
}

std::string checksums_text(const checked_values& values) {
  std::string text;
  for (const auto& [name, value] : values) text += name + " " + hex(fnv1a(value)) + "\n";
  return text;
}

std::vector<std::string> changed_values(const std::string& checksums, const checked_values& values) {
  std::set<std::string> changed, listed;
  std::istringstream lines(checksums);
  for (std::string line; std::getline(lines, line);) {
    if (line.empty()) continue;
    const auto space = line.rfind(' ');
    const std::string name = space == std::string::npos ? line : line.substr(0, space);
    listed.insert(name);
    const auto found = values.find(name);
    if (found == values.end() || space == std::string::npos || line.substr(space + 1) != hex(fnv1a(found->second)))
      changed.insert(name);
  }
  for (const auto& entry : values)
    if (!listed.count(entry.first)) changed.insert(entry.first);
  return {changed.begin(), changed.end()};
}

}  // namespace flecsi_lite::io
