// The checks of derived quantities (derived_values.hh).
#include "flecsi_lite/runtime/derived_values.hh"

#include "flecsi_lite/runtime/parameters.hh"

#include <cmath>
#include <sstream>
#include <string>

namespace flecsi_lite::runtime {

namespace {
std::string derived_problem(const std::string& program, const std::string& what, double value, const std::string& keys,
                            const std::string& requirement) {
  std::ostringstream message;
  message.precision(6);
  message << program << ": " << what << " = " << value << " (from " << keys << ") " << requirement;
  return message.str();
}
}  // namespace

double checked_length(const std::string& program, const std::string& what, double value, const std::string& keys) {
  if (!(value >= smallest_length && value <= largest_length))
    throw parameter_error(derived_problem(program, what, value, keys, "must be a length in [1e-50, 1e50]"));
  return value;
}

double checked_positive(const std::string& program, const std::string& what, double value, const std::string& keys) {
  if (!(std::isfinite(value) && value > 0))
    throw parameter_error(derived_problem(program, what, value, keys, "must be finite and > 0"));
  return value;
}

std::int64_t checked_count(const std::string& program, const std::string& what, double value, const std::string& keys) {
  if (!(value >= 0 && value <= most_particles))
    throw parameter_error(derived_problem(program, what, value, keys, "must be a count in [0, 2^40]"));
  return std::llround(value);
}

}  // namespace flecsi_lite::runtime
