#include "flecsi_lite/runtime/options.hh"

#include "flecsi_lite/util/edit_distance.hh"

#include <Kokkos_Core.hpp>

#include <sstream>

namespace flecsi_lite::runtime {

options& options::flag(const std::string& name, const std::string& help) {
  order_.push_back(name);
  specs_[name] = {kind::flag, "", help, ""};
  return *this;
}

options& options::value(const std::string& name, const std::string& metavar, const std::string& help,
                        const std::string& default_value) {
  order_.push_back(name);
  specs_[name] = {kind::value, metavar, help, default_value};
  return *this;
}

options& options::repeated(const std::string& name, const std::string& metavar, const std::string& help) {
  order_.push_back(name);
  specs_[name] = {kind::repeated, metavar, help, ""};
  return *this;
}

options& options::positional(const std::string& name, const std::string& help, bool required) {
  positionals_.push_back({name, help, required});
  return *this;
}

const options::spec& options::find(const std::string& name) const {
  if (auto it = specs_.find(name); it != specs_.end()) return it->second;
  std::string message = "unknown option '--" + name + "'";
  if (auto near = util::nearest_name(name, order_); !near.empty()) message += "; did you mean '--" + near + "'?";
  throw options_error(message + " (see --help)");
}

void options::parse(int argc, const char* const* argv) {
  std::size_t next_positional = 0;
  for (int i = 1; i < argc; ++i) {
    std::string arg = argv[i];
    if (arg.rfind("--", 0) == 0 && arg.size() > 2) {
      std::string name = arg.substr(2), inline_value;
      const bool has_inline = name.find('=') != std::string::npos;
      if (has_inline) {
        inline_value = name.substr(name.find('=') + 1);
        name = name.substr(0, name.find('='));
      }
      const spec& s = find(name);
      if (s.type == kind::flag) {
        if (has_inline) throw options_error("option '--" + name + "' takes no value");
        given_[name].push_back("1");
        continue;
      }
      if (!has_inline) {
        if (i + 1 >= argc) throw options_error("option '--" + name + "' needs a value " + s.metavar);
        inline_value = argv[++i];
      }
      if (s.type == kind::value) given_[name].clear();
      given_[name].push_back(inline_value);
    } else {
      if (next_positional >= positionals_.size()) throw options_error("unexpected argument '" + arg + "' (see --help)");
      given_[positionals_[next_positional++].name].push_back(arg);
    }
  }
  if (has("help")) return;  // --help needs nothing else
  for (std::size_t p = next_positional; p < positionals_.size(); ++p)
    if (positionals_[p].required) throw options_error("missing argument <" + positionals_[p].name + "> (see --help)");
}

bool options::has(const std::string& name) const {
  auto it = given_.find(name);
  return it != given_.end() && !it->second.empty();
}

std::string options::get(const std::string& name) const {
  if (auto it = given_.find(name); it != given_.end() && !it->second.empty()) return it->second.back();
  if (auto it = specs_.find(name); it != specs_.end()) return it->second.default_value;
  return {};
}

std::vector<std::string> options::all(const std::string& name) const {
  auto it = given_.find(name);
  return it == given_.end() ? std::vector<std::string>{} : it->second;
}

std::string options::help(const std::string& program) const {
  std::ostringstream out;
  out << "usage: " << program << " [options]";
  for (auto& p : positionals_) out << (p.required ? " <" : " [") << p.name << (p.required ? ">" : "]");
  out << "\n";
  if (!description_.empty()) out << "\n" << description_ << "\n";
  if (!positionals_.empty()) {
    out << "\narguments:\n";
    for (auto& p : positionals_) out << "  " << p.name << "\n      " << p.help << "\n";
  }
  out << "\noptions:\n";
  for (auto& name : order_) {
    const spec& s = specs_.at(name);
    out << "  --" << name << (s.type == kind::flag ? "" : " " + s.metavar) << "\n      " << s.help;
    if (!s.default_value.empty()) out << " (default: " << s.default_value << ")";
    if (s.type == kind::repeated) out << " (repeatable)";
    out << "\n";
  }
  // Only the runtime hands argv to Kokkos (before parsing); serial tools never start Kokkos.
  if (Kokkos::is_initialized())
    out << "\nOptions --kokkos-* (--kokkos-num-threads=N, ...) are passed to Kokkos: --help-kokkos lists them.\n";
  return out.str();
}

}  // namespace flecsi_lite::runtime
