// The narray topology on 1 to 4 ranks: the blocks partition the index space in rank order with
// sizes that differ by at most one; ghosts are the halo entities beside each block (wrapping when
// periodic, none beyond a non-periodic boundary); neighbor() agrees with modular arithmetic; the
// ghost plan sends exactly what other ranks receive; ghost copies deliver the owners' values for
// fields of any type and halo width; instances of one field definition keep separate values.
#include <catch2/catch.hpp>

#include "flecsi_lite/data.hh"
#include "flecsi_lite/execution.hh"
#include "flecsi_lite/runtime/context.hh"
#include "flecsi_lite/topology/narray.hh"

#include <array>
#include <cstdint>
#include <stdexcept>

using namespace flecsi_lite;
using topology::narray;

namespace {
const field<double>::definition<narray> real_values{"real_values"};
const field<std::int64_t>::definition<narray> integer_values{"integer_values"};
const field<std::array<double, 2>>::definition<narray> pair_values{"pair_values"};

MPI_Comm comm() { return runtime::communicator(); }
bool all_ranks(bool mine) {
  int in = mine, out = 0;
  MPI_Allreduce(&in, &out, 1, MPI_INT, MPI_LAND, comm());
  return out;
}
std::uint64_t sum_over_ranks(std::uint64_t mine) {
  std::uint64_t total = 0;
  MPI_Allreduce(&mine, &total, 1, MPI_UINT64_T, MPI_SUM, comm());
  return total;
}
/// Distance from a to b going up, modulo n (the periodic offset of b seen from a).
long wrapped_offset(std::size_t a, std::size_t b, std::size_t n) {
  const long d = (static_cast<long>(b) - static_cast<long>(a) + static_cast<long>(n)) % static_cast<long>(n);
  return d > static_cast<long>(n) / 2 ? d - static_cast<long>(n) : d;
}

// The owners' values are functions of the global index, so a ghost can be checked where it lands.
double real_of(std::size_t g) { return 0.25 * static_cast<double>(g) - 3; }
void write_owned(const narray& n, field<double>::accessor<wo> r, field<std::int64_t>::accessor<wo> k,
                 field<std::array<double, 2>>::accessor<wo> p) {
  for (std::size_t i = 0; i < r.size(); ++i) {
    const std::size_t g = n.global_index(i);
    r(i) = real_of(g), k(i) = -static_cast<std::int64_t>(g) * 7, p(i) = {double(g), -double(g)};
  }
}
bool ghosts_hold_owner_values(const narray& n, field<double>::accessor<ro, ro> r,
                              field<std::int64_t>::accessor<ro, ro> k,
                              field<std::array<double, 2>>::accessor<ro, ro> p) {
  bool ok = r.size() == n.total_size() && k.size() == n.total_size() && p.size() == n.total_size();
  for (std::size_t i = n.owned_size(); i < n.total_size(); ++i) {
    const std::size_t g = n.global_index(i);
    ok &=
      r(i) == real_of(g) && k(i) == -static_cast<std::int64_t>(g) * 7 && p(i)[0] == double(g) && p(i)[1] == -double(g);
  }
  return ok;
}
void fill(field<double>::accessor<wo> r, double value) {
  for (std::size_t i = 0; i < r.size(); ++i) r(i) = value;
}
bool all_equal(field<double>::accessor<ro, ro> r, double value) {
  bool ok = true;
  for (std::size_t i = 0; i < r.size(); ++i) ok &= r(i) == value;
  return ok;
}
}  // namespace

TEST_CASE("the blocks partition the index space in rank order, balanced within one entity") {
  for (std::size_t global : {std::size_t(8), std::size_t(97), std::size_t(1000)}) {
    narray n(global, 1, false);
    std::uint64_t below = 0, owned = n.owned_size();
    MPI_Exscan(&owned, &below, 1, MPI_UINT64_T, MPI_SUM, comm());
    if (runtime::rank() == 0) below = 0;  // MPI_Exscan leaves rank 0's result undefined
    std::uint64_t smallest = owned, largest = owned;
    MPI_Allreduce(MPI_IN_PLACE, &smallest, 1, MPI_UINT64_T, MPI_MIN, comm());
    MPI_Allreduce(MPI_IN_PLACE, &largest, 1, MPI_UINT64_T, MPI_MAX, comm());
    CHECK(sum_over_ranks(owned) == global);
    CHECK(largest - smallest <= 1);
    CHECK(all_ranks(n.first_global() == below));
    bool contiguous = true;
    for (std::size_t i = 0; i < n.owned_size(); ++i) contiguous &= n.global_index(i) == n.first_global() + i;
    CHECK(all_ranks(contiguous));
    CHECK(n.global_size() == global);
  }
}

TEST_CASE("ghosts are the halo entities on each side, wrapping only when periodic") {
  const int rank = runtime::rank(), size = runtime::size();
  for (bool periodic : {false, true})
    for (std::size_t halo : {std::size_t(0), std::size_t(1), std::size_t(3)}) {
      const std::size_t global = 40;
      narray n(global, halo, periodic);
      const std::size_t left = (periodic || rank > 0) ? halo : 0, right = (periodic || rank + 1 < size) ? halo : 0;
      CHECK(n.ghost_size() == left + right);
      CHECK(n.total_size() == n.owned_size() + left + right);
      const std::size_t first = n.first_global(), end = first + n.owned_size();
      bool placed = true;
      for (std::size_t g = 0; g < left; ++g)
        placed &= n.global_index(n.owned_size() + g) == (first + global - halo + g) % global;
      for (std::size_t g = 0; g < right; ++g) placed &= n.global_index(n.owned_size() + left + g) == (end + g) % global;
      CHECK(all_ranks(placed));
      // Every ghost is owned by another rank, or by this one when one rank wraps around.
      bool foreign = true;
      for (std::size_t i = n.owned_size(); i < n.total_size(); ++i) {
        const std::size_t g = n.global_index(i);
        foreign &= size == 1 ? periodic : (g < first || g >= end);
      }
      CHECK(all_ranks(foreign));
    }
}

TEST_CASE("neighbor() is modular arithmetic on global indices, npos past a wall") {
  for (bool periodic : {false, true}) {
    const std::size_t global = 31, halo = 2;
    narray n(global, halo, periodic);
    bool consistent = true;
    for (std::size_t i = 0; i < n.owned_size(); ++i)
      for (long offset = -static_cast<long>(halo); offset <= static_cast<long>(halo); ++offset) {
        const long target = static_cast<long>(n.global_index(i)) + offset;
        const std::size_t local = n.neighbor(i, offset);
        if (!periodic && (target < 0 || target >= static_cast<long>(global))) {
          consistent &= local == narray::npos;
          continue;
        }
        consistent &=
          local < n.total_size() && wrapped_offset(n.global_index(i), n.global_index(local), global) == offset;
      }
    CHECK(all_ranks(consistent));
  }
}

TEST_CASE("the ghost plan sends exactly the owned entities other ranks receive") {
  for (bool periodic : {false, true}) {
    const std::size_t halo = 2;
    narray n(24, halo, periodic);
    std::uint64_t sent = 0, received = 0;
    bool edge_only = true;
    for (const auto& peer : n.plan().peers) {
      received += peer.receive_count;
      sent += peer.send.size();
      for (std::size_t i : peer.send) edge_only &= i < halo || i + halo >= n.owned_size();
    }
    CHECK(received == n.ghost_size());
    CHECK(sum_over_ranks(sent) == sum_over_ranks(received));
    CHECK(all_ranks(edge_only));
  }
}

TEST_CASE("ghost copies deliver the owners' values for fields of several types") {
  for (bool periodic : {false, true})
    for (std::size_t halo : {std::size_t(1), std::size_t(2), std::size_t(5)}) {
      narray n(60, halo, periodic);
      execute<write_owned>(n, real_values(n), integer_values(n), pair_values(n));
      CHECK(all_ranks(execute<ghosts_hold_owner_values>(n, real_values(n), integer_values(n), pair_values(n)).get()));
    }
}

TEST_CASE("instances of one field definition hold separate values") {
  narray small(16, 1, true), large(64, 2, true);
  execute<fill>(real_values(small), 1.5);
  execute<fill>(real_values(large), -2.0);
  CHECK(all_ranks(execute<all_equal>(real_values(small), 1.5).get()));
  CHECK(all_ranks(execute<all_equal>(real_values(large), -2.0).get()));
  CHECK(host_view(real_values(large)).extent(0) == large.total_size());
}

TEST_CASE("ranks may own nothing when there is no halo; a block smaller than the halo is an error") {
  narray sparse(2, 0, false);  // fewer entities than ranks at 3 and 4 ranks
  CHECK(sum_over_ranks(sparse.owned_size()) == 2);
  CHECK(sparse.ghost_size() == 0);
  if (runtime::size() > 1) CHECK_THROWS_AS(narray(runtime::size(), 2, false), std::invalid_argument);
}
