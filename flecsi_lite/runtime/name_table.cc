// The messages of name tables and choice keys (name_table.hh), one wording for both.
#include "flecsi_lite/runtime/name_table.hh"

#include "flecsi_lite/util/edit_distance.hh"

namespace flecsi_lite::runtime {

std::string choices_text(const std::vector<std::string>& choices) {
  std::string text = "one of:";
  for (std::size_t i = 0; i < choices.size(); ++i) text += (i ? ", " : " ") + choices[i];
  return text;
}

std::string not_a_choice(std::string_view text, const std::vector<std::string>& choices) {
  std::string message = "'" + std::string(text) + "' is not " + choices_text(choices);
  if (const auto near = util::nearest_name(text, choices); !near.empty()) message += "; did you mean '" + near + "'?";
  return message;
}

}  // namespace flecsi_lite::runtime
