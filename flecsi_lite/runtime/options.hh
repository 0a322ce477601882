// Command-line options: flags (--name), values (--name VALUE or --name=VALUE), repeatable values
// and positional arguments, with generated --help text and "did you mean" errors.
#pragma once

#include <map>
#include <stdexcept>
#include <string>
#include <vector>

namespace flecsi_lite::runtime {

struct options_error : std::runtime_error {
  using std::runtime_error::runtime_error;
};

class options {
 public:
  explicit options(std::string description = {}) : description_(std::move(description)) {}

  options& flag(const std::string& name, const std::string& help);
  options& value(const std::string& name, const std::string& metavar, const std::string& help,
                 const std::string& default_value = {});
  /// A value option that may be given several times (e.g. --set key=value).
  options& repeated(const std::string& name, const std::string& metavar, const std::string& help);
  options& positional(const std::string& name, const std::string& help, bool required = true);

  /// Parses argv[1..argc); throws options_error naming the offending argument.
  void parse(int argc, const char* const* argv);

  bool has(const std::string& name) const;                      // flag given, or value/positional present
  std::string get(const std::string& name) const;               // value, default, or "" when absent
  std::vector<std::string> all(const std::string& name) const;  // every occurrence
  /// Usage, options and defaults; with a note on --kokkos-* options when Kokkos is running.
  std::string help(const std::string& program) const;

 private:
  enum class kind { flag, value, repeated };
  struct spec {
    kind type;
    std::string metavar, help, default_value;
  };
  struct positional_spec {
    std::string name, help;
    bool required;
  };
  const spec& find(const std::string& name) const;

  std::string description_;
  std::vector<std::string> order_;
  std::map<std::string, spec> specs_;
  std::vector<positional_spec> positionals_;
  std::map<std::string, std::vector<std::string>> given_;
};

}  // namespace flecsi_lite::runtime
