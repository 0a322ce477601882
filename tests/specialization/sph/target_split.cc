// The split of the pair tasks' targets into interior (every neighbour owned) and boundary (some
// neighbour a ghost), on 1, 2 and 4 ranks: the two sets partition the targets as the lists say,
// and the interior launch (owned privileges only) neither reads a ghost nor touches a boundary
// target, so it may run while the ghost copies travel.
#include "sph_setup.hh"

#include <catch2/catch.hpp>

#include <mpi.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

namespace {
using namespace sph_test;
constexpr int D = 2;
using f = sph::fields<D>;

std::uint64_t global_sum(std::uint64_t local) {
  std::uint64_t total = 0;
  MPI_Allreduce(&local, &total, 1, MPI_UINT64_T, MPI_SUM, flecsi_lite::runtime::communicator());
  return total;
}

struct split_run : sph::simulation<D> {
  split_run() {
    physics.adaptive_smoothing_length = false;  // rho depends on x and m only: a launch can be repeated
    load_lattice(*this, {16, true, 1.0, 1.0, 0.2});
    sph::update_neighbours(*this);
  }
};
}  // namespace

TEST_CASE("interior and boundary targets partition the owned particles as the lists say") {
  split_run s;
  const auto& n = s.neighbours.host();
  const std::size_t owned = s.particles->owned_size();
  REQUIRE(n.size() == owned);
  REQUIRE(n.interior.size() + n.boundary.size() == owned);
  std::vector<int> seen(owned, 0);
  for (const auto* set : {&n.interior, &n.boundary})
    for (std::size_t i = 0; i < set->size(); ++i) {
      if (i > 0) CHECK((*set)[i - 1] < (*set)[i]);  // ascending
      ++seen[(*set)[i]];
    }
  for (std::size_t a = 0; a < owned; ++a) CHECK(seen[a] == 1);
  const sph::neighbour_walk<D> walk(n);
  const auto ghost_neighbours = [&](std::size_t a) {
    const sph::neighbour_row<D> row = walk.row(a);
    std::size_t count = 0;
    for (std::size_t j = 0; j < row.size(); ++j) count += row.neighbour(j) >= owned;
    return count;
  };
  for (const auto a : n.interior) CHECK(ghost_neighbours(a) == 0);
  for (const auto a : n.boundary) CHECK(ghost_neighbours(a) > 0);
  // One rank holds no ghost (periodic images are owned data); more ranks have both kinds.
  const int ranks = flecsi_lite::runtime::size();
  CHECK((global_sum(n.boundary.size()) > 0) == (ranks > 1));
  CHECK(global_sum(n.interior.size()) > 0);
}

TEST_CASE("the interior launch reads no ghost and writes no boundary target") {
  split_run s;
  sph::update_density(s);
  auto& p = *s.particles;
  const std::size_t owned = p.owned_size();
  const auto reference = flecsi_lite::host_view(f::density(p));
  std::vector<double> rho_before(reference.data(), reference.data() + owned);
  // Ghost positions and masses made poison, boundary densities marked: the interior launch must
  // reproduce the interior densities bitwise and leave the marks.
  const double poison = std::numeric_limits<double>::quiet_NaN(), mark = -12345.0;
  auto x = flecsi_lite::host_view(f::position()(p));
  auto m = flecsi_lite::host_view(f::mass()(p));
  auto rho = flecsi_lite::host_view(f::density(p));
  for (std::size_t b = owned; b < p.owned_size() + p.ghost_size(); ++b) {
    x(b).fill(poison);
    m(b) = poison;
  }
  for (const auto a : s.neighbours.host().boundary) rho(a) = mark;
  for (const auto a : s.neighbours.host().interior) rho(a) = 0;
  const double worst = flecsi_lite::execute<sph::compute_density<D, flecsi_lite::na>>(
                         s.neighbours, s.physics, 0.0, f::position()(p), f::mass()(p), f::kind(p),
                         f::smoothing_length()(p), f::density(p), f::omega(p), f::velocity(p).only_if(false),
                         f::velocity_divergence(p).only_if(false), f::velocity_curl(p).only_if(false))
                         .get();
  CHECK(std::isfinite(worst));
  const auto after = flecsi_lite::host_view(f::density(p));
  for (const auto a : s.neighbours.host().interior) CHECK(after(a) == rho_before[a]);
  for (const auto a : s.neighbours.host().boundary) CHECK(after(a) == mark);
}
