#include "flecsi_lite/topology/narray/narray.hh"

#include "flecsi_lite/data/ghost_plan_builder.hh"
#include "flecsi_lite/runtime/context.hh"

#include <stdexcept>
#include <string>

namespace flecsi_lite::topology {
namespace {
std::size_t block_begin(std::size_t n, int rank, int size) {
  return n * static_cast<std::size_t>(rank) / static_cast<std::size_t>(size);
}
}  // namespace

narray::narray(std::size_t global_size, std::size_t halo, bool periodic)
    : global_size_(global_size), halo_(halo), periodic_(periodic) {
  const int rank = runtime::rank(), size = runtime::size();
  first_ = block_begin(global_size, rank, size);
  const std::size_t owned = block_begin(global_size, rank + 1, size) - first_;
  for (int r = 0; r < size; ++r)
    if (block_begin(global_size, r + 1, size) - block_begin(global_size, r, size) < halo)
      throw std::invalid_argument("narray: " + std::to_string(global_size) + " entities over " + std::to_string(size) +
                                  " ranks leave a block smaller than the halo of " + std::to_string(halo));
  left_ghosts_ = (periodic || rank > 0) ? halo : 0;
  right_ghosts_ = (periodic || rank + 1 < size) ? halo : 0;
  set_sizes(owned, left_ghosts_ + right_ghosts_);

  // Ghost slots and their owners: the left halo comes from the previous rank, the right halo
  // from the next (the same rank, or this one, when few ranks wrap around a periodic domain).
  std::vector<int> owners;
  std::vector<std::uint64_t> ids;
  for (std::size_t g = 0; g < left_ghosts_ + right_ghosts_; ++g) {
    owners.push_back(g < left_ghosts_ ? (rank + size - 1) % size : (rank + 1) % size);
    ids.push_back(global_index(owned + g));
  }
  const std::size_t first = first_;
  set_plan(data::build_ghost_plan(
    owners, ids, [first](std::uint64_t id) { return std::size_t(id - first); }, runtime::communicator()));
}

std::size_t narray::global_index(std::size_t local) const {
  const std::size_t owned = owned_size();
  if (local < owned) return first_ + local;
  const std::size_t g = local - owned;
  if (g < left_ghosts_) return (first_ + global_size_ - halo_ + g) % global_size_;
  return (first_ + owned + (g - left_ghosts_)) % global_size_;
}

std::size_t narray::neighbor(std::size_t i, long offset) const {
  const long target = static_cast<long>(i) + offset;
  const long owned = static_cast<long>(owned_size());
  if (target >= 0 && target < owned) return static_cast<std::size_t>(target);
  if (target < 0) {
    if (-target > static_cast<long>(left_ghosts_)) return npos;
    return owned_size() + left_ghosts_ + static_cast<std::size_t>(target);
  }
  if (target - owned >= static_cast<long>(right_ghosts_)) return npos;
  return owned_size() + left_ghosts_ + static_cast<std::size_t>(target - owned);
}

}  // namespace flecsi_lite::topology
