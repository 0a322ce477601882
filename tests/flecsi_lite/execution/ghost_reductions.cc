// reduce_ghosts<op>: every ghost value reaches its owner and is combined there, on any rank count,
// periodic and not; the result equals a brute-force combination of every rank's ghosts gathered
// on every rank; later readers see the combined values, and the ghosts are stale after it.
#include <catch2/catch.hpp>

#include "flecsi_lite/data.hh"
#include "flecsi_lite/execution.hh"
#include "flecsi_lite/runtime/context.hh"
#include "flecsi_lite/topology/narray.hh"
#include "index_values.hh"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <utility>

using namespace flecsi_lite;
using testing::all_ranks;
using testing::fill_scaled_index;
using testing::ghosts_hold;
using topology::narray;

namespace {
const field<double>::definition<narray> total{"total"};
const field<double>::definition<narray> fresh{"fresh"};

/// A contribution that tells its sender and its entity apart: 1000 (rank + 1) + global index.
double contribution(int rank, std::size_t global) { return 1000.0 * (rank + 1) + double(global); }

/// Owned values `owned_value`, each ghost slot this rank's contribution to its entity.
void contribute(const narray& n, field<double>::accessor<wo, wo> f, double owned_value) {
  for (std::size_t i = 0; i < f.owned_size(); ++i) f(i) = owned_value;
  for (std::size_t i = f.owned_size(); i < f.size(); ++i) f(i) = contribution(runtime::rank(), n.global_index(i));
}

/// Every rank's (global index, contribution) of its ghosts, on every rank.
std::vector<std::pair<double, double>> all_ghost_contributions(const narray& n) {
  std::vector<double> mine;
  for (std::size_t i = n.owned_size(); i < n.owned_size() + n.ghost_size(); ++i)
    mine.insert(mine.end(), {double(n.global_index(i)), contribution(runtime::rank(), n.global_index(i))});
  int count = static_cast<int>(mine.size());
  std::vector<int> counts(runtime::size()), offsets(runtime::size());
  MPI_Allgather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, runtime::communicator());
  for (int r = 1; r < runtime::size(); ++r) offsets[r] = offsets[r - 1] + counts[r - 1];
  std::vector<double> all(offsets.back() + counts.back());
  MPI_Allgatherv(mine.data(), count, MPI_DOUBLE, all.data(), counts.data(), offsets.data(), MPI_DOUBLE,
                 runtime::communicator());
  std::vector<std::pair<double, double>> pairs;
  for (std::size_t i = 0; i < all.size(); i += 2) pairs.emplace_back(all[i], all[i + 1]);
  return pairs;
}

template<class Op>
bool combined_as_brute_force(narray& n, double owned_value) {
  const auto pairs = all_ghost_contributions(n);
  auto values = host_view(total(n));
  bool equal = true;
  for (std::size_t i = 0; i < n.owned_size(); ++i) {
    double expected = owned_value;  // the ghosts combined in the senders' rank order
    for (const auto& [global, value] : pairs)
      if (global == double(n.global_index(i))) expected = Op::combine(expected, value);
    equal &= values(i) == expected;
  }
  return equal;
}
}  // namespace

TEST_CASE("reduce_ghosts combines every ghost into its owner, as brute force does") {
  for (bool periodic : {false, true})
    for (std::size_t halo : {1, 3}) {
      narray n(37, halo, periodic);
      execute<contribute>(n, total(n), 0.0);
      reduce_ghosts<reduction::sum>(total(n));
      CHECK(all_ranks(combined_as_brute_force<reduction::sum>(n, 0.0)));
      execute<contribute>(n, total(n), 2500.0);  // below some contributions, above others
      reduce_ghosts<reduction::min>(total(n)).get();
      CHECK(all_ranks(combined_as_brute_force<reduction::min>(n, 2500.0)));
      execute<contribute>(n, total(n), 2500.0);
      reduce_ghosts<reduction::max>(total(n));
      CHECK(all_ranks(combined_as_brute_force<reduction::max>(n, 2500.0)));
    }
}

TEST_CASE("after reduce_ghosts readers see the combined values, and the ghosts are copied again") {
  auto& ex = execution::executor::instance();
  narray n(40, 2, true);
  execute<contribute>(n, total(n), 0.0);
  reduce_ghosts<reduction::sum>(total(n));
  // Each entity within the halo of a block's end is a ghost of the next block (or of its own
  // block's periodic image): exactly one contribution per end it lies near.
  const auto sums = host_view(total(n));
  bool each_from_its_neighbour = true;
  for (std::size_t i = 0; i < n.owned_size(); ++i) {
    const bool near_start = i < n.halo(), near_end = i + n.halo() >= n.owned_size();
    const int left = (runtime::rank() + runtime::size() - 1) % runtime::size();
    const int right = (runtime::rank() + 1) % runtime::size();
    const double g = double(n.global_index(i));
    const double expected = (near_start ? contribution(left, g) : 0.0) + (near_end ? contribution(right, g) : 0.0);
    each_from_its_neighbour &= sums(i) == expected;
  }
  CHECK(all_ranks(each_from_its_neighbour));
  execute<fill_scaled_index>(n, total(n), 1.0);  // ordered after the reduction (write after write)
  const auto copies = ex.ghost_copies_started();
  CHECK(all_ranks(execute<ghosts_hold>(n, total(n), 1.0).get()));
  CHECK(ex.ghost_copies_started() == copies + 1);
  wait_all();
}

TEST_CASE("reduce_ghosts without defined ghost values is a clear error") {
  narray n(20, 1, true);
  execute<fill_scaled_index>(n, fresh(n), 1.0);  // owned values only: the ghosts are stale
  CHECK_THROWS_WITH(reduce_ghosts<reduction::sum>(fresh(n)), Catch::Contains("reduce_ghosts of field 'fresh'"));
  wait_all();
}
