// One key of a parameter schema: its type, default, bounds or choices, and the conversion and
// checking of value text (parameters.hh).
#include "flecsi_lite/runtime/parameters.hh"

#include "flecsi_lite/runtime/name_table.hh"
#include "flecsi_lite/runtime/parameter_text.hh"

#include <algorithm>

namespace flecsi_lite::runtime {

using detail::parse_boolean;
using detail::parse_integer;
using detail::parse_real;
using detail::parse_real_list;
using detail::parse_string;
using detail::shortest_real;

const char* parameter_type_name(parameter_type type) {
  switch (type) {
    case parameter_type::real:
      return "real";
    case parameter_type::integer:
      return "integer";
    case parameter_type::boolean:
      return "boolean";
    case parameter_type::string:
      return "string";
    case parameter_type::real_list:
      return "list of reals";
  }
  return "unknown";
}

// ---- declarations -------------------------------------------------------------------------

parameter_declaration::parameter_declaration(std::string name, parameter_type type, std::string description)
    : name_(std::move(name)), type_(type), description_(std::move(description)) {}

parameter_declaration& parameter_declaration::set_default(parameter_value value) {
  // The variant's alternatives follow the order of parameter_type.
  if (value.index() != static_cast<std::size_t>(type_))
    throw std::logic_error("parameter schema: the default of '" + name_ + "' is not a " + parameter_type_name(type_));
  default_ = std::move(value);
  return *this;
}

namespace {
void require_bounded_type(parameter_type type, const std::string& name) {
  if (type != parameter_type::real && type != parameter_type::integer && type != parameter_type::real_list)
    throw std::logic_error("parameter schema: '" + name + "' is a " + parameter_type_name(type) +
                           " and cannot have bounds");
}
}  // namespace

parameter_declaration& parameter_declaration::at_least(double minimum) {
  require_bounded_type(type_, name_);
  lower_ = bound{minimum, true};
  return *this;
}
parameter_declaration& parameter_declaration::greater_than(double minimum) {
  require_bounded_type(type_, name_);
  lower_ = bound{minimum, false};
  return *this;
}
parameter_declaration& parameter_declaration::at_most(double maximum) {
  require_bounded_type(type_, name_);
  upper_ = bound{maximum, true};
  return *this;
}
parameter_declaration& parameter_declaration::less_than(double maximum) {
  require_bounded_type(type_, name_);
  upper_ = bound{maximum, false};
  return *this;
}
parameter_declaration& parameter_declaration::length(std::size_t count) {
  if (type_ != parameter_type::real_list)
    throw std::logic_error("parameter schema: '" + name_ + "' is not a list and cannot have a length");
  length_ = count;
  return *this;
}

std::string parameter_declaration::bounds_text() const {
  if (lower_ && upper_)
    return std::string("in ") + (lower_->inclusive ? "[" : "(") + shortest_real(lower_->value) + ", " +
           shortest_real(upper_->value) + (upper_->inclusive ? "]" : ")");
  if (lower_) return std::string(lower_->inclusive ? ">= " : "> ") + shortest_real(lower_->value);
  if (upper_) return std::string(upper_->inclusive ? "<= " : "< ") + shortest_real(upper_->value);
  return "";
}

std::string parameter_declaration::constraint_text() const {
  const std::string bounds = bounds_text();
  if (type_ == parameter_type::real_list) {
    std::string text = length_ ? std::to_string(*length_) + " elements" : "";
    if (!bounds.empty()) text += (text.empty() ? "elements " : " ") + bounds;
    return text;
  }
  if (!choices_.empty()) return choices_text(choices_);
  return bounds;
}

std::string parameter_declaration::violation(const parameter_value& value) const {
  const auto outside = [&](double v) {
    return (lower_ && (lower_->inclusive ? v < lower_->value : v <= lower_->value)) ||
           (upper_ && (upper_->inclusive ? v > upper_->value : v >= upper_->value));
  };
  switch (type_) {
    case parameter_type::real:
    case parameter_type::integer: {
      const double v =
        type_ == parameter_type::real ? std::get<double>(value) : static_cast<double>(std::get<std::int64_t>(value));
      if (outside(v)) return format(value) + " is out of range (must be " + constraint_text() + ")";
      return "";
    }
    case parameter_type::real_list: {
      const auto& values = std::get<std::vector<double>>(value);
      if (length_ && values.size() != *length_)
        return format(value) + " has " + std::to_string(values.size()) + " elements, not " + std::to_string(*length_);
      for (std::size_t i = 0; i < values.size(); ++i)
        if (outside(values[i]))
          return "element " + std::to_string(i + 1) + " (" + shortest_real(values[i]) + ") is out of range (must be " +
                 bounds_text() + ")";
      return "";
    }
    case parameter_type::string: {
      const auto& text = std::get<std::string>(value);
      if (choices_.empty() || std::find(choices_.begin(), choices_.end(), text) != choices_.end()) return "";
      return not_a_choice(text, choices_);
    }
    case parameter_type::boolean:
      return "";
  }
  return "";
}

std::optional<parameter_value> parameter_declaration::interpret(const std::string& text, std::string& problem) const {
  std::optional<parameter_value> value;
  switch (type_) {
    case parameter_type::real:
      if (auto v = parse_real(text, problem)) value = *v;
      break;
    case parameter_type::integer:
      if (auto v = parse_integer(text, problem)) value = *v;
      break;
    case parameter_type::boolean:
      if (auto v = parse_boolean(text, problem)) value = *v;
      break;
    case parameter_type::string:
      if (auto v = parse_string(text, problem)) value = *v;
      break;
    case parameter_type::real_list:
      if (auto v = parse_real_list(text, problem)) value = *v;
      break;
  }
  if (!value) return std::nullopt;
  problem = violation(*value);
  if (!problem.empty()) return std::nullopt;
  return value;
}

std::string parameter_declaration::format(const parameter_value& value) {
  struct formatter {
    std::string operator()(double v) const { return shortest_real(v); }
    std::string operator()(std::int64_t v) const { return std::to_string(v); }
    std::string operator()(bool v) const { return v ? "true" : "false"; }
    std::string operator()(const std::string& v) const { return '"' + v + '"'; }
    std::string operator()(const std::vector<double>& v) const {
      std::string text;
      for (std::size_t i = 0; i < v.size(); ++i) text += (i ? ", " : "") + shortest_real(v[i]);
      return text;
    }
  };
  return std::visit(formatter{}, value);
}

}  // namespace flecsi_lite::runtime
