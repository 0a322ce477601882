// The keys an application accepts (parameters.hh): declaration in order, and the help text.
#include "flecsi_lite/runtime/parameters.hh"

#include "flecsi_lite/runtime/parameter_text.hh"

namespace flecsi_lite::runtime {

parameter_declaration& parameter_schema::declare(const std::string& name, parameter_type type,
                                                 const std::string& description) {
  if (!detail::is_key(name))
    throw std::logic_error("parameter schema: '" + name + "' is not a valid key (letters, digits, '_', '.', '-')");
  if (find(name)) throw std::logic_error("parameter schema: '" + name + "' is declared twice");
  return declarations_.emplace_back(name, type, description);
}

parameter_declaration& parameter_schema::real(const std::string& name, const std::string& description) {
  return declare(name, parameter_type::real, description);
}
parameter_declaration& parameter_schema::integer(const std::string& name, const std::string& description) {
  return declare(name, parameter_type::integer, description);
}
parameter_declaration& parameter_schema::boolean(const std::string& name, const std::string& description) {
  return declare(name, parameter_type::boolean, description);
}
parameter_declaration& parameter_schema::string(const std::string& name, const std::string& description) {
  return declare(name, parameter_type::string, description);
}
parameter_declaration& parameter_schema::choice(const std::string& name, std::vector<std::string> choices,
                                                const std::string& description) {
  if (choices.empty()) throw std::logic_error("parameter schema: '" + name + "' has no choices");
  auto& declaration = declare(name, parameter_type::string, description);
  declaration.choices_ = std::move(choices);
  return declaration;
}
parameter_declaration& parameter_schema::real_list(const std::string& name, const std::string& description) {
  return declare(name, parameter_type::real_list, description);
}

void parameter_schema::add(const parameter_schema& other) {
  for (const auto& declaration : other.declarations()) {
    if (find(declaration.name()))
      throw std::logic_error("parameter schema: '" + declaration.name() + "' is declared twice");
    declarations_.push_back(declaration);
  }
}

const parameter_declaration* parameter_schema::find(const std::string& name) const {
  for (const auto& declaration : declarations_)
    if (declaration.name() == name) return &declaration;
  return nullptr;
}

std::vector<std::string> parameter_schema::names() const {
  std::vector<std::string> result;
  for (const auto& declaration : declarations_) result.push_back(declaration.name());
  return result;
}

std::string parameter_schema::help() const {
  std::string text;
  for (const auto& d : declarations_) {
    text += "  " + d.name() + " (" + parameter_type_name(d.type());
    text += d.required() ? ", required" : ", default " + parameter_declaration::format(*d.fallback());
    if (const auto constraint = d.constraint_text(); !constraint.empty()) text += ", " + constraint;
    text += ")\n      " + d.description() + "\n";
  }
  return text;
}

}  // namespace flecsi_lite::runtime
