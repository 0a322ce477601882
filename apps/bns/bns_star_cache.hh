// Relaxed stars made once: a binary set-up with star_cache = DIR takes its star from
// DIR/bns_star_<hash>.h5part, where the hash (64-bit FNV-1a, Fowler, Noll & Vo) is over the keys
// that make the relaxed star (particles, EOS and its constants, kernel, eta, viscosity, Courant
// factor, gravity, mass, radius, G and the star's relaxation settings), so a changed key makes
// another file and an unchanged one reuses it (Phantom's users relax their stars once the same
// way, with a relaxed star file). The file holds every key as a root attribute "cache_<key>".
#pragma once

#include "flecsi_lite/runtime.hh"

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

namespace bns {

/// The keys, their values as the resolved parameters write them (in this order), their hash and
/// the file.
struct star_cache_entry {
  std::vector<std::pair<std::string, std::string>> keys;
  std::uint64_t hash = 0;
  std::string path;
};

/// The entry of the star a binary with these parameters uses; `gravitational_constant` is the
/// run's G (from the unit keys with physical_constants). `folder` is star_cache.
star_cache_entry star_cache_entry_for(const flecsi_lite::runtime::parameters& parameters, double gravitational_constant,
                                      const std::string& folder);

/// 64-bit FNV-1a of `text`.
std::uint64_t fnv1a_64(const std::string& text);

}  // namespace bns
