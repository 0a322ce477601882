// Name tables of enumerations: one list of (name, value) pairs per enum that drives parsing of a
// choice key, its allowed values in the schema and --parameters-help, "did you mean" on a
// misspelled name, and the name written back in the resolved parameters.
//
//   enum class kernel_type { cubic_spline, wendland_c2 };
//   inline const name_table<kernel_type> kernel_names{
//     "kernel", {{"cubic_spline", kernel_type::cubic_spline}, {"wendland_c2", kernel_type::wendland_c2}}};
//   kernel_names.value("wendland_c2");            // kernel_type::wendland_c2
//   kernel_names.name(kernel_type::cubic_spline);  // "cubic_spline"
#pragma once

#include <initializer_list>
#include <stdexcept>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace flecsi_lite::runtime {

/// "one of: a, b, c".
std::string choices_text(const std::vector<std::string>& choices);
/// "'x' is not one of: a, b, c; did you mean 'a'?" (the suggestion only for a plausible typo).
std::string not_a_choice(std::string_view text, const std::vector<std::string>& choices);

/// The names of the values of an enumeration `Enum`, in the order they are listed (the order of
/// the help text). `noun` names what the values are ("kernel", "equation of state") in errors.
template<class Enum>
class name_table {
 public:
  name_table(std::string noun, std::initializer_list<std::pair<const char*, Enum>> entries) : noun_(std::move(noun)) {
    for (const auto& [name, value] : entries) {
      for (std::size_t i = 0; i < names_.size(); ++i)
        if (names_[i] == name || values_[i] == value)
          throw std::logic_error("name table of " + noun_ + ": '" + name + "' or its value is listed twice");
      names_.emplace_back(name);
      values_.push_back(value);
    }
    if (names_.empty()) throw std::logic_error("name table of " + noun_ + " is empty");
  }

  /// The name of `value`; a value missing from the table is a logic_error.
  const std::string& name(Enum value) const {
    for (std::size_t i = 0; i < values_.size(); ++i)
      if (values_[i] == value) return names_[i];
    throw std::logic_error("name table of " + noun_ + ": a value has no name");
  }
  /// The value called `name`; throws std::invalid_argument "unknown kernel 'x': 'x' is not one
  /// of: ...; did you mean ...?" for any other name.
  Enum value(std::string_view name) const {
    for (std::size_t i = 0; i < names_.size(); ++i)
      if (names_[i] == name) return values_[i];
    throw std::invalid_argument("unknown " + noun_ + " '" + std::string(name) + "': " + not_a_choice(name, names_));
  }
  const std::vector<std::string>& names() const { return names_; }
  const std::vector<Enum>& values() const { return values_; }
  const std::string& noun() const { return noun_; }

 private:
  std::string noun_;
  std::vector<std::string> names_;
  std::vector<Enum> values_;
};

}  // namespace flecsi_lite::runtime
