// Text form of attribute values (see attribute_value.hh).
#include "flecsi_lite/io/attribute_value.hh"

#include <cstdio>

namespace flecsi_lite::io {

std::string to_string(const attribute_value& value) {
  if (auto* s = std::get_if<std::string>(&value)) return *s;
  if (auto* i = std::get_if<std::int64_t>(&value)) return std::to_string(*i);
  char text[32];
  std::snprintf(text, sizeof text, "%.17g", std::get<double>(value));
  return text;
}

}  // namespace flecsi_lite::io
