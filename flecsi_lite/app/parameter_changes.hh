// Parameters a restart may change: the resolved parameter text a checkpoint stores compared with
// this run's key by key, the keys that only steer the run (files, cadences, limits) left free.
#pragma once

#include "flecsi_lite/runtime/parameter_block.hh"

#include <map>
#include <set>
#include <string>
#include <vector>

namespace flecsi_lite::app {

/// The key allow_parameter_changes: "none", "all", or keys separated by commas or spaces.
struct restart_settings {
  std::string allow_parameter_changes = "none";
};
runtime::parameter_block<restart_settings> restart_parameters();

/// The keys the frame declares that never change a solution: the file keys, the run limits,
/// used_parameters_file and allow_parameter_changes itself.
std::set<std::string> frame_free_keys();

/// The values of the `key = value` lines of a resolved parameter text (runtime::parameters::
/// resolved_text(): quoted strings, `# origin` comments), as text.
std::map<std::string, std::string> parameter_values(const std::string& text);

struct parameter_difference {
  std::string key, before, now;  ///< "(absent)" for a key only one text has
};

/// The keys whose values differ between `before` and `now`, except `free_keys`.
std::vector<parameter_difference> parameter_differences(const std::string& before, const std::string& now,
                                                        const std::set<std::string>& free_keys);

/// Throws parameter_error when `now` differs from `before` (the parameters of `checkpoint`) in a
/// key outside `free_keys` that `allowed` (restart_settings text) does not name, listing every such
/// key with both values. A key named in `allowed` that neither text has is an error too.
void require_same_parameters(const std::string& checkpoint, const std::string& before, const std::string& now,
                             const std::set<std::string>& free_keys, const std::string& allowed);

}  // namespace flecsi_lite::app
