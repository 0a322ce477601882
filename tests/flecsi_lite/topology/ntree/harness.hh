// Shared pieces of the distributed ntree tests: initial spreads of a particle set over the ranks,
// loading a set into an ntree<D> through a task, and gathers of per-rank results in rank order.
#pragma once

#include "flecsi_lite/data.hh"
#include "flecsi_lite/execution.hh"
#include "flecsi_lite/runtime/context.hh"
#include "flecsi_lite/topology/ntree.hh"
#include "flecsi_lite/topology/ntree/reference/brute_force.hh"
#include "tests/flecsi_lite/topology/ntree/particle_sets.hh"

#include <mpi.h>

#include <cstdint>
#include <unordered_map>
#include <vector>

namespace ntree_mpi_test {

namespace nt = flecsi_lite::topology::ntree;
using flecsi_lite::field;
using flecsi_lite::na;
using flecsi_lite::ro;
using flecsi_lite::rw;
using flecsi_lite::wo;
using ntree_test::particle_set;

/// Where the particles start before distribute().
enum class start {
  rank_zero,       // everything on rank 0
  random_ranks,    // each particle on a pseudo-random rank (from its id)
  reversed_blocks  // contiguous blocks of the input, the last block on rank 0
};

inline int rank() { return flecsi_lite::runtime::rank(); }
inline int size() { return flecsi_lite::runtime::size(); }

/// Indices into `set` of the particles that start on this rank.
template<int D>
std::vector<std::size_t> starting_here(const particle_set<D>& set, start how) {
  std::vector<std::size_t> mine;
  const std::size_t n = set.size(), p = static_cast<std::size_t>(size()), r = static_cast<std::size_t>(rank());
  for (std::size_t i = 0; i < n; ++i) {
    std::size_t owner = 0;
    if (how == start::random_ranks)
      owner = (set.id[i] * 0xbf58476d1ce4e5b9ull >> 29) % p;
    else if (how == start::reversed_blocks)
      owner = p - 1 - i * p / n;
    if (owner == r) mine.push_back(i);
  }
  return mine;
}

template<int D>
void fill(const particle_set<D>& set, const std::vector<std::size_t>& mine,
          typename field<nt::point<D>>::template accessor<wo> x, field<std::uint64_t>::accessor<wo> id,
          field<double>::accessor<wo> m, field<double>::accessor<wo> h) {
  for (std::size_t i = 0; i < mine.size(); ++i) {
    x(i) = set.x[mine[i]];
    id(i) = set.id[mine[i]];
    m(i) = set.m[mine[i]];
    h(i) = set.h[mine[i]];
  }
}

/// Sizes `tree` to this rank's starting particles and fills the built-in fields by a task.
template<int D>
void load(nt::ntree<D>& tree, const particle_set<D>& set, start how) {
  const auto mine = starting_here(set, how);
  tree.resize(mine.size());
  using topology = nt::ntree<D>;
  flecsi_lite::execute<fill<D>>(set, mine, topology::position(tree), topology::id(tree), topology::mass(tree),
                                topology::smoothing_length(tree))
    .wait();
}

/// Every rank's `mine` concatenated in rank order (on every rank).
template<class T>
std::vector<T> gather_all(const std::vector<T>& mine) {
  const MPI_Comm comm = flecsi_lite::runtime::communicator();
  int bytes = static_cast<int>(mine.size() * sizeof(T));
  std::vector<int> counts(size()), offsets(size());
  MPI_Allgather(&bytes, 1, MPI_INT, counts.data(), 1, MPI_INT, comm);
  int total = 0;
  for (int r = 0; r < size(); ++r) {
    offsets[r] = total;
    total += counts[r];
  }
  std::vector<T> all(static_cast<std::size_t>(total) / sizeof(T));
  MPI_Allgatherv(mine.data(), bytes, MPI_BYTE, all.data(), counts.data(), offsets.data(), MPI_BYTE, comm);
  return all;
}

inline bool all_ranks(bool mine) {
  int in = mine, out = 0;
  MPI_Allreduce(&in, &out, 1, MPI_INT, MPI_LAND, flecsi_lite::runtime::communicator());
  return out != 0;
}

/// Index in `set` of each id.
template<int D>
std::unordered_map<std::uint64_t, std::size_t> index_by_id(const particle_set<D>& set) {
  std::unordered_map<std::uint64_t, std::size_t> index;
  for (std::size_t i = 0; i < set.size(); ++i) index.emplace(set.id[i], i);
  return index;
}

}  // namespace ntree_mpi_test
