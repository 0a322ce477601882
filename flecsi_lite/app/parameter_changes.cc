// Comparison of two resolved parameter texts for restarts (parameter_changes.hh).
#include "flecsi_lite/app/parameter_changes.hh"

#include "flecsi_lite/app/file_settings.hh"
#include "flecsi_lite/app/run_limits.hh"
#include "flecsi_lite/runtime/parameter_text.hh"
#include "flecsi_lite/runtime/parameters.hh"

#include <sstream>

namespace flecsi_lite::app {

namespace {
std::set<std::string> keys_of(const runtime::parameter_schema& schema) {
  std::set<std::string> keys;
  for (const auto& d : schema.declarations()) keys.insert(d.name());
  return keys;
}
}  // namespace

runtime::parameter_block<restart_settings> restart_parameters() {
  runtime::parameter_block<restart_settings> block;
  block.string("allow_parameter_changes", &restart_settings::allow_parameter_changes,
               "keys a restart may set otherwise than its checkpoint (none, all, or key names)");
  return block;
}

std::set<std::string> frame_free_keys() {
  std::set<std::string> keys = keys_of(file_parameters().schema());
  for (const auto& key : keys_of(run_limit_parameters().schema())) keys.insert(key);
  for (const auto& key : keys_of(restart_parameters().schema())) keys.insert(key);
  keys.insert("used_parameters_file");
  return keys;
}

std::map<std::string, std::string> parameter_values(const std::string& text) {
  // The parameter files' own reading of a line: its line ends, '#' outside quotes, trimming.
  using namespace runtime::detail;
  std::map<std::string, std::string> values;
  for (const std::string& raw : split_lines(text)) {
    const std::string line = trim(strip_comment(raw));
    const auto equals = line.find('=');
    if (equals == std::string::npos) continue;
    values[trim(line.substr(0, equals))] = trim(line.substr(equals + 1));
  }
  return values;
}

std::vector<parameter_difference> parameter_differences(const std::string& before, const std::string& now,
                                                        const std::set<std::string>& free_keys) {
  const auto a = parameter_values(before), b = parameter_values(now);
  std::map<std::string, parameter_difference> differences;
  for (const auto& [key, value] : a) {
    const auto found = b.find(key);
    if (found == b.end() || found->second != value)
      differences[key] = {key, value, found == b.end() ? "(absent)" : found->second};
  }
  for (const auto& [key, value] : b)
    if (!a.count(key)) differences[key] = {key, "(absent)", value};
  std::vector<parameter_difference> result;
  for (auto& [key, difference] : differences)
    if (!free_keys.count(key)) result.push_back(std::move(difference));
  return result;
}

void require_same_parameters(const std::string& checkpoint, const std::string& before, const std::string& now,
                             const std::set<std::string>& free_keys, const std::string& allowed) {
  std::set<std::string> allowed_keys;
  {
    std::string list = allowed;
    for (char& c : list)
      if (c == ',') c = ' ';
    std::istringstream words(list);
    for (std::string word; words >> word;) allowed_keys.insert(word);
  }
  if (allowed_keys.count("all")) return;
  allowed_keys.erase("none");
  const auto a = parameter_values(before), b = parameter_values(now);
  for (const auto& key : allowed_keys)
    if (!a.count(key) && !b.count(key))
      throw runtime::parameter_error("allow_parameter_changes names '" + key + "', which is no parameter key");
  std::string listed;
  for (const auto& d : parameter_differences(before, now, free_keys))
    if (!allowed_keys.count(d.key)) listed += "\n  " + d.key + ": checkpoint " + d.before + ", this run " + d.now;
  if (!listed.empty())
    throw runtime::parameter_error(
      "restart from '" + checkpoint +
      "': these parameters differ from the checkpoint's "
      "and would change the solution:" +
      listed +
      "\nset them as the checkpoint has "
      "them, or allow the change with --set allow_parameter_changes=KEY[,KEY...] (or all)");
}

}  // namespace flecsi_lite::app
