// The checks an app offers on its command line (`--check-l1 RHO,P,V`): declared with the names
// of their bounds and the range of each, parsed at start-up before anything runs, so that a bad
// value is a usage error (exit status 2) naming the option and the value, never a failure after
// the whole run.
//
//   definition.checks = {{"check-l1", {"RHO", "P", "V"}, "exit 1 if an L1 error exceeds its bound"}};
//   if (run.checks().has("check-l1")) { const std::vector<double>& b = run.checks().bounds("check-l1"); ... }
#pragma once

#include "flecsi_lite/runtime/options.hh"

#include <limits>
#include <map>
#include <string>
#include <vector>

namespace flecsi_lite::app {

/// One check, `--<name> B1,B2,...`: one finite number in [minimum, maximum] per bound.
struct check_option {
  std::string name;                 ///< the option without "--" (e.g. "check-l1")
  std::vector<std::string> bounds;  ///< the bounds' names in order, shown in --help (e.g. RHO, P, V)
  std::string help;                 ///< what the check compares; exit status 1 when it fails
  double minimum = 0;               ///< the smallest value of a bound
  double maximum = std::numeric_limits<double>::max();
};

/// The checks given on the command line, each with its bounds.
class check_values {
 public:
  bool has(const std::string& name) const { return bounds_.count(name) > 0; }
  /// The bounds of the check `name`, which must have been given (has).
  const std::vector<double>& bounds(const std::string& name) const;
  /// The single bound of a check with one (e.g. --check-energy TOL).
  double bound(const std::string& name) const { return bounds(name).at(0); }

 private:
  friend check_values parse_checks(const std::vector<check_option>&, const runtime::options&);
  std::map<std::string, std::vector<double>> bounds_;
};

/// Declares every check as a value option of `options`.
void declare_checks(const std::vector<check_option>& checks, runtime::options& options);

/// The bounds of the checks given in `options`. Throws runtime::parameter_error naming the option,
/// its value and what is wrong (not a number, not finite, out of range, too few or too many).
check_values parse_checks(const std::vector<check_option>& checks, const runtime::options& options);

/// One bound's text (blanks around it allowed) as a number; NaN when it is not one whole number.
double parse_bound(const std::string& text);

}  // namespace flecsi_lite::app
