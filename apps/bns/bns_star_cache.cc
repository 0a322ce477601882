// The key of a cached relaxed star and its file (bns_star_cache.hh).
#include "bns_star_cache.hh"

#include <cstdio>

namespace bns {

std::uint64_t fnv1a_64(const std::string& text) {
  std::uint64_t hash = 14695981039346656037ull;  // the offset basis
  for (const unsigned char byte : text) {
    hash ^= byte;
    hash *= 1099511628211ull;  // the 64-bit FNV prime
  }
  return hash;
}

star_cache_entry star_cache_entry_for(const flecsi_lite::runtime::parameters& parameters, double gravitational_constant,
                                      const std::string& folder) {
  using flecsi_lite::runtime::parameter_declaration;
  // Every key the relaxed star depends on (the binary's own keys, such as separation, do not).
  static const char* const names[] = {"particles",
                                      "star_mass",
                                      "star_radius",
                                      "eos",
                                      "polytropic_exponent",
                                      "gamma",
                                      "kernel",
                                      "eta",
                                      "viscosity_alpha",
                                      "viscosity_beta",
                                      "viscosity_switch",
                                      "conductivity_alpha",
                                      "courant",
                                      "gravity_theta",
                                      "gravity_criterion",
                                      "star_relaxation_time",
                                      "star_relaxation_min_time",
                                      "relaxation_tolerance",
                                      "star_damping_time"};
  star_cache_entry entry;
  std::string text;
  for (const char* name : names) {
    entry.keys.push_back({name, parameter_declaration::format(parameters.value(name))});
    text += entry.keys.back().first + " = " + entry.keys.back().second + "\n";
  }
  char value[32];
  std::snprintf(value, sizeof value, "%.17g", gravitational_constant);
  entry.keys.push_back({"gravitational_constant", value});
  text += std::string("gravitational_constant = ") + value + "\n";
  entry.hash = fnv1a_64(text);
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(entry.hash));
  entry.path = (folder.empty() ? std::string(".") : folder) + "/bns_star_" + hex + ".h5part";
  return entry;
}

}  // namespace bns
