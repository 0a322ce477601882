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

std::int64_t checked_particles(const std::string& program, double value, const std::string& keys, double memory) {
  const std::int64_t count = checked_count(program, "particles", value, keys);
  const double needed = double(count) * least_bytes_per_particle;
  if (needed <= memory) return count;
  std::ostringstream message;
  message.precision(3);
  message << "need at least " << needed << " bytes (" << least_bytes_per_particle
          << " bytes a particle), more than the " << memory
          << " bytes this job may use (physical memory, ulimit -v and control-group limits of its nodes): "
          << "lower " << keys << " or run on more nodes";
  throw parameter_error(derived_problem(program, "particles", value, keys, message.str()));
}

}  // namespace flecsi_lite::runtime
