// Encoding and broadcast of an HDF5 file's metadata listing (see metadata_listing.hh).
#include "flecsi_lite/io/detail/metadata_listing.hh"

#include <algorithm>
#include <cstdint>
#include <stdexcept>

namespace flecsi_lite::io {

const std::vector<std::string>& metadata_listing::datasets_of(const std::string& group) const {
  static const std::vector<std::string> none;
  const auto found = datasets.find(group);
  return found == datasets.end() ? none : found->second;
}

namespace {
// Each string as its length, ':' and its bytes (HDF5 names may hold any byte but '/' and NUL).
void put(std::string& out, const std::string& text) { out += std::to_string(text.size()) + ':' + text; }

std::string take(const std::string& in, std::size_t& at) {
  const std::size_t colon = in.find(':', at);
  if (colon == std::string::npos || colon == at || colon - at > 19)
    throw std::runtime_error("damaged metadata listing");
  const std::uint64_t size = std::stoull(in.substr(at, colon - at));
  if (size > in.size() - colon - 1) throw std::runtime_error("damaged metadata listing");
  at = colon + 1 + size;
  return in.substr(colon + 1, size);
}

std::size_t take_count(const std::string& in, std::size_t& at) {
  const std::string text = take(in, at);
  if (text.empty() || text.find_first_not_of("0123456789") != std::string::npos)
    throw std::runtime_error("damaged metadata listing");
  return std::stoull(text);
}
}  // namespace

std::string encode(const metadata_listing& listing) {
  std::string out;
  put(out, std::to_string(listing.groups.size()));
  for (const auto& group : listing.groups) put(out, group);
  put(out, std::to_string(listing.datasets.size()));
  for (const auto& [group, names] : listing.datasets) {
    put(out, group);
    put(out, std::to_string(names.size()));
    for (const auto& name : names) put(out, name);
  }
  return out;
}

metadata_listing decode_listing(const std::string& bytes) {
  metadata_listing listing;
  std::size_t at = 0;
  for (std::size_t n = take_count(bytes, at); n > 0; --n) listing.groups.push_back(take(bytes, at));
  for (std::size_t n = take_count(bytes, at); n > 0; --n) {
    const std::string group = take(bytes, at);
    auto& names = listing.datasets[group];
    for (std::size_t k = take_count(bytes, at); k > 0; --k) names.push_back(take(bytes, at));
  }
  if (at != bytes.size()) throw std::runtime_error("damaged metadata listing");
  return listing;
}

metadata_listing broadcast_listing(const metadata_listing& listing, int root, MPI_Comm comm) {
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  std::string bytes = rank == root ? encode(listing) : std::string();
  unsigned long long size = bytes.size();
  MPI_Bcast(&size, 1, MPI_UNSIGNED_LONG_LONG, root, comm);
  bytes.resize(size);
  // In pieces below 2^31 bytes: MPI counts are int.
  for (unsigned long long offset = 0; offset < size; offset += 1ull << 30) {
    const int piece = static_cast<int>(std::min<unsigned long long>(1ull << 30, size - offset));
    MPI_Bcast(bytes.data() + offset, piece, MPI_CHAR, root, comm);
  }
  return rank == root ? listing : decode_listing(bytes);
}

}  // namespace flecsi_lite::io
