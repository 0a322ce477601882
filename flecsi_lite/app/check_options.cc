// The app's checks as declared options, parsed at start-up (check_options.hh).
#include "flecsi_lite/app/check_options.hh"

#include "flecsi_lite/runtime/parameters.hh"

#include <cmath>
#include <cstdlib>
#include <sstream>
#include <stdexcept>

namespace flecsi_lite::app {

namespace {
std::string joined(const std::vector<std::string>& names) {
  std::string text;
  for (const auto& name : names) text += (text.empty() ? "" : ",") + name;
  return text;
}

std::string range_text(const check_option& check) {
  std::ostringstream text;
  text << "finite numbers >= " << check.minimum;
  if (check.maximum < std::numeric_limits<double>::max()) text << " and <= " << check.maximum;
  return text.str();
}
}  // namespace

double parse_bound(const std::string& text) {
  const auto first = text.find_first_not_of(" \t");
  const auto last = text.find_last_not_of(" \t");
  if (first == std::string::npos) return std::nan("");
  const std::string trimmed = text.substr(first, last - first + 1);
  char* end = nullptr;
  const double value = std::strtod(trimmed.c_str(), &end);  // 1e999: inf, refused as not finite
  return end == trimmed.c_str() + trimmed.size() ? value : std::nan("");
}

const std::vector<double>& check_values::bounds(const std::string& name) const {
  const auto found = bounds_.find(name);
  if (found == bounds_.end()) throw std::logic_error("check_values: --" + name + " was not given");
  return found->second;
}

void declare_checks(const std::vector<check_option>& checks, runtime::options& options) {
  for (const auto& check : checks)
    options.value(check.name, joined(check.bounds), check.help + " (" + range_text(check) + ")");
}

check_values parse_checks(const std::vector<check_option>& checks, const runtime::options& options) {
  check_values values;
  for (const auto& check : checks) {
    if (!options.has(check.name)) continue;
    const std::string given = options.get(check.name);
    const std::string usage = "; give " + std::to_string(check.bounds.size()) + " comma-separated " +
                              range_text(check) + ": --" + check.name + " " + joined(check.bounds);
    const auto refuse = [&](const std::string& why) {
      throw runtime::parameter_error("--" + check.name + " '" + given + "': " + why + usage);
    };
    std::vector<std::string> items;
    std::stringstream in(given);
    for (std::string item; std::getline(in, item, ',');) items.push_back(item);
    if (!given.empty() && given.back() == ',') items.emplace_back();
    if (items.size() != check.bounds.size())
      refuse(std::to_string(items.size()) + " value" + (items.size() == 1 ? "" : "s") + " for " +
             std::to_string(check.bounds.size()) + " bound" + (check.bounds.size() == 1 ? "" : "s"));
    std::vector<double> bounds;
    for (std::size_t k = 0; k < items.size(); ++k) {
      const double value = parse_bound(items[k]);
      const std::string named = check.bounds[k] + " = '" + items[k] + "'";
      if (std::isnan(value)) refuse(named + " is not a number");
      if (!std::isfinite(value)) refuse(named + " is not finite");
      if (value < check.minimum || value > check.maximum) refuse(named + " is out of range");
      bounds.push_back(value);
    }
    values.bounds_[check.name] = bounds;
  }
  return values;
}

}  // namespace flecsi_lite::app
