// Parameter files in the style of FleCSPH's .par files: `key = value` lines (ended by LF, CRLF or
// a lone CR), `#` comments (also after a value), blank lines; a schema declared by the application
// gives every key its type, default (or none: required), allowed range or choices and a one-line
// description. Any key can be overridden on the command line (--set key=value, applied after the
// file). Settings structs declare their keys once, bound to their members, with parameter_block
// (parameter_block.hh).
//
//   parameter_schema schema;
//   schema.real("gamma", "adiabatic index").default_value(5.0 / 3).range(1, 3);
//   schema.integer("particles", "number of particles").at_least(1);          // required
//   schema.choice("kernel", {"cubic_spline", "wendland_c2"}, "smoothing kernel")
//     .default_value("cubic_spline");
//   auto p = parameters::load(schema, "sod.par", opts.all("set"));
//   double gamma = p.get<double>("gamma");
//
// Every mistake in the input (unknown key, with the nearest valid key suggested; malformed line;
// a value starting with '=' (`key == 3`); a key longer than 200 characters, without suggestion;
// key given twice in the file; value of the wrong type; out of range or not among the choices;
// missing required key; missing or unreadable file) throws parameter_error, whose message names
// the file and line (or the command-line argument), the key and the bad value. Mistakes of the
// program (asking for a key the schema lacks, or with the wrong type) throw std::logic_error.
#pragma once

#include "flecsi_lite/runtime/context.hh"

#include <mpi.h>

#include <cstdint>
#include <deque>
#include <initializer_list>
#include <limits>
#include <map>
#include <optional>
#include <stdexcept>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

namespace flecsi_lite::runtime {

struct parameter_error : std::runtime_error {
  using std::runtime_error::runtime_error;
};

enum class parameter_type { real, integer, boolean, string, real_list };

/// "real", "integer", "boolean", "string" or "list of reals".
const char* parameter_type_name(parameter_type type);

using parameter_value = std::variant<double, std::int64_t, bool, std::string, std::vector<double>>;

/// One key of a schema: its type, default, constraints and description. The builder functions
/// return *this so that they chain; a default that breaks the constraints is a logic_error.
class parameter_declaration {
 public:
  parameter_declaration(std::string name, parameter_type type, std::string description);

  /// The default (converted to the declared type; a mismatch is a logic_error). Keys without a
  /// default are required.
  template<class T>
  parameter_declaration& default_value(const T& value) {
    if constexpr (std::is_same_v<T, bool>)
      return set_default(value);
    else if constexpr (std::is_integral_v<T>) {
      if (type_ == parameter_type::real) return set_default(static_cast<double>(value));
      return set_default(static_cast<std::int64_t>(value));
    } else if constexpr (std::is_floating_point_v<T>)
      return set_default(static_cast<double>(value));
    else if constexpr (std::is_convertible_v<T, std::string>)
      return set_default(std::string(value));
    else
      return set_default(std::vector<double>(value.begin(), value.end()));
  }
  parameter_declaration& default_value(std::initializer_list<double> values) {
    return set_default(std::vector<double>(values));
  }

  /// Bounds on reals, integers and every element of a list of reals.
  parameter_declaration& at_least(double minimum);
  parameter_declaration& greater_than(double minimum);
  parameter_declaration& at_most(double maximum);
  parameter_declaration& less_than(double maximum);
  parameter_declaration& range(double minimum, double maximum) { return at_least(minimum).at_most(maximum); }
  /// Number of elements of a list of reals.
  parameter_declaration& length(std::size_t count);

  const std::string& name() const { return name_; }
  parameter_type type() const { return type_; }
  const std::string& description() const { return description_; }
  const std::optional<parameter_value>& fallback() const { return default_; }
  bool required() const { return !default_.has_value(); }
  const std::vector<std::string>& choices() const { return choices_; }

  /// Converts text to a value of this key's type and checks the constraints; returns the value
  /// or sets `problem` to what is wrong (e.g. "'abc' is not a real number").
  std::optional<parameter_value> interpret(const std::string& text, std::string& problem) const;
  /// What makes `value` break the constraints (e.g. "1.5 is out of range (must be in [0, 1])"),
  /// or "" when it is allowed.
  std::string violation(const parameter_value& value) const;
  /// The value as parameter-file text (reals with just enough digits to read back exactly).
  static std::string format(const parameter_value& value);
  /// e.g. "in [0, 1]", "> 0", "one of: a, b", "3 elements >= 0"; "" without constraints.
  std::string constraint_text() const;

 private:
  friend class parameter_schema;
  parameter_declaration& set_default(parameter_value value);
  std::string bounds_text() const;  // e.g. "in [0, 1]", "> 0"; "" without bounds

  struct bound {
    double value;
    bool inclusive;
  };
  std::string name_;
  parameter_type type_;
  std::string description_;
  std::optional<parameter_value> default_;
  std::optional<bound> lower_, upper_;
  std::optional<std::size_t> length_;
  std::vector<std::string> choices_;
};

/// The keys an application accepts, in declaration order.
class parameter_schema {
 public:
  parameter_declaration& real(const std::string& name, const std::string& description);
  parameter_declaration& integer(const std::string& name, const std::string& description);
  parameter_declaration& boolean(const std::string& name, const std::string& description);
  parameter_declaration& string(const std::string& name, const std::string& description);
  /// A string restricted to `choices`.
  parameter_declaration& choice(const std::string& name, std::vector<std::string> choices,
                                const std::string& description);
  parameter_declaration& real_list(const std::string& name, const std::string& description);
  /// Every key of `other`, after the keys declared so far (a key declared twice is a logic_error).
  void add(const parameter_schema& other);

  /// nullptr when `name` is not declared.
  const parameter_declaration* find(const std::string& name) const;
  std::vector<std::string> names() const;
  const std::deque<parameter_declaration>& declarations() const { return declarations_; }
  /// One line per key: name, type, default or "required", constraints and description.
  std::string help() const;

 private:
  parameter_declaration& declare(const std::string& name, parameter_type type, const std::string& description);
  std::deque<parameter_declaration> declarations_;  // a deque keeps references valid
};

/// The resolved parameter set: every key of the schema with its value and where it came from.
class parameters {
 public:
  /// Defaults, then the file `path` ("" for none), then `overrides` ("key=value", as given to
  /// --set; a later one wins over an earlier one). Rank 0 reads the file and broadcasts its text;
  /// every rank parses it, so errors are identical on every rank. Collective over `comm`.
  static parameters load(const parameter_schema& schema, const std::string& path,
                         const std::vector<std::string>& overrides = {}, MPI_Comm comm = communicator());
  /// Same from text already read; `source` names it in messages. No communication.
  static parameters parse(const parameter_schema& schema, const std::string& text, const std::string& source,
                          const std::vector<std::string>& overrides = {});

  /// The value of `name` as T: double/float for reals, any integral type for integers (checked
  /// to fit), bool, std::string for strings and choices, std::vector<double> for lists.
  template<class T>
  T get(const std::string& name) const;

  /// The value of `name`, whatever its type.
  const parameter_value& value(const std::string& name) const;
  /// "default", "file sod.par:12" or "command line".
  const std::string& origin(const std::string& name) const;
  /// Every key as `key = value  # origin`, in declaration order; itself a valid parameter file.
  std::string resolved_text() const;
  const parameter_schema& schema() const { return schema_; }

 private:
  struct entry {
    parameter_value value;
    std::string origin;
  };
  explicit parameters(parameter_schema schema) : schema_(std::move(schema)) {}
  const entry& lookup(const std::string& name, parameter_type wanted, const char* cxx_type) const;

  parameter_schema schema_;
  std::map<std::string, entry> values_;
  std::string sources_;  // what the values came from, for the header of resolved_text()
};

template<class T>
T parameters::get(const std::string& name) const {
  if constexpr (std::is_same_v<T, bool>) {
    return std::get<bool>(lookup(name, parameter_type::boolean, "bool").value);
  } else if constexpr (std::is_floating_point_v<T>) {
    return static_cast<T>(std::get<double>(lookup(name, parameter_type::real, "a floating type").value));
  } else if constexpr (std::is_integral_v<T>) {
    const std::int64_t v = std::get<std::int64_t>(lookup(name, parameter_type::integer, "an integral type").value);
    const bool fits = std::is_signed_v<T> ? v >= static_cast<std::int64_t>(std::numeric_limits<T>::min()) &&
                                              (v < 0 || static_cast<std::uint64_t>(v) <=
                                                          static_cast<std::uint64_t>(std::numeric_limits<T>::max()))
                                          : v >= 0 && static_cast<std::uint64_t>(v) <= std::numeric_limits<T>::max();
    if (!fits)
      throw parameter_error("parameter '" + name + "' = " + std::to_string(v) + " (" + origin(name) +
                            ") does not fit the integer type the program reads it as");
    return static_cast<T>(v);
  } else if constexpr (std::is_same_v<T, std::string>) {
    return std::get<std::string>(lookup(name, parameter_type::string, "std::string").value);
  } else {
    static_assert(std::is_same_v<T, std::vector<double>>,
                  "parameters are read as floating, integral, bool, std::string or std::vector<double>");
    return std::get<std::vector<double>>(lookup(name, parameter_type::real_list, "std::vector<double>").value);
  }
}

}  // namespace flecsi_lite::runtime
