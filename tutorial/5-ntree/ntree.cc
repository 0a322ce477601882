// Tutorial chapter 5: particles on the distributed ntree topology. Each rank creates some
// particles, distribute() sorts them over the ranks along a space-filling curve and adds GHOST
// copies of the particles other ranks hold within reach, and find_neighbours() searches the local
// tree. The toy: an SPH-like density sum with the poly6 kernel (Mueller et al. 2003), then a
// neighbour average of a user field (its ghosts copied by the executor), both checked against a
// direct sum over all particles.
//
//   mpirun -np 2 tutorial_5_ntree [--particles 3000]
#include "flecsi_lite/topology/ntree.hh"
#include "flecsi_lite/data.hh"
#include "flecsi_lite/execution.hh"
#include "flecsi_lite/runtime.hh"

#include <mpi.h>

#include <cmath>
#include <cstdint>
#include <vector>

using namespace flecsi_lite;
namespace nt = flecsi_lite::topology::ntree;
using tree_type = nt::ntree<3>;

namespace {
const field<double>::definition<tree_type> density{"density"};
const field<double>::definition<tree_type> neighbour_mean{"neighbour_mean"};

// Particle i's position in the unit cube, the same on every rank (a counter-based hash).
nt::point<3> position_of(std::uint64_t i) {
  nt::point<3> x;
  for (std::uint64_t k = 0; k < 3; ++k) {
    std::uint64_t z = (3 * i + k + 1) * 0x9e3779b97f4a7c15ull;
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ull;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebull;
    x[k] = double((z ^ (z >> 31)) >> 11) * 0x1.0p-53;
  }
  return x;
}
double distance_squared(const nt::point<3>& a, const nt::point<3>& b) {
  return (a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) + (a[2] - b[2]) * (a[2] - b[2]);
}
// Poly6 kernel of support radius R: 315 / (64 pi R^3) (1 - r^2/R^2)^3, integral 1.
double kernel(double r2, double R) { return 315 / (64 * M_PI * R * R * R) * std::pow(1 - r2 / (R * R), 3); }

void create(std::uint64_t first, std::uint64_t total, double h, field<nt::point<3>>::accessor<wo> x,
            field<std::uint64_t>::accessor<wo> id, field<double>::accessor<wo> m, field<double>::accessor<wo> hs) {
  forall(x.size(), [&](std::size_t i) {
    id(i) = first + i, x(i) = position_of(first + i), m(i) = 1.0 / double(total), hs(i) = h;
  });
}
// Gather: the neighbours b of a are those with |x_a - x_b| < support * h_a (a itself included).
void density_sum(const nt::neighbour_lists& lists, double support, field<nt::point<3>>::accessor<ro, ro> x,
                 field<double>::accessor<ro, ro> m, field<double>::accessor<ro, ro> h,
                 field<double>::accessor<wo> rho) {
  forall(rho.size(), [&](std::size_t a) {
    double sum = 0;
    for (std::size_t j = lists.offsets[a]; j < lists.offsets[a + 1]; ++j) {
      const std::size_t b = lists.neighbours[j];
      sum += m(b) * kernel(distance_squared(x(a), x(b)), support * h(a));
    }
    rho(a) = sum;
  });
}
// Reads the densities of ghost neighbours: the executor copies them from their owners first.
void average(const nt::neighbour_lists& lists, field<double>::accessor<ro, ro> rho, field<double>::accessor<wo> mean) {
  forall(mean.size(), [&](std::size_t a) {
    double sum = 0;
    for (std::size_t j = lists.offsets[a]; j < lists.offsets[a + 1]; ++j) sum += rho(lists.neighbours[j]);
    mean(a) = sum / double(lists.count(a));
  });
}
}  // namespace

int main(int argc, char** argv) {
  runtime::options options("Tutorial 5: distribute particles, find neighbours, a density sum.");
  options.value("particles", "N", "number of particles", "3000");
  runtime::runtime rt(argc, argv, options);
  if (!rt.proceed()) return rt.exit_code();
  const std::uint64_t total = std::stoull(rt.opts().get("particles"));
  const std::uint64_t ranks = runtime::size(), rank = runtime::rank();
  const std::uint64_t first = total * rank / ranks, count = total * (rank + 1) / ranks - first;
  const double h = 0.5 * std::cbrt(40 / (4.0 / 3.0 * M_PI * double(total)));  // ~40 neighbours

  tree_type tree(tree_type::config{}, count);  // `count` particles here, fields zero
  execute<create>(first, total, h, tree_type::position(tree), tree_type::id(tree), tree_type::mass(tree),
                  tree_type::smoothing_length(tree));
  tree.distribute();  // collective: particles move to their ranks, ghosts arrive
  nt::neighbour_lists lists;
  tree.find_neighbours(lists, nt::interaction::gather);
  const double support = tree.settings().support;
  execute<density_sum>(lists, support, tree_type::position(tree), tree_type::mass(tree),
                       tree_type::smoothing_length(tree), density(tree));
  const auto copies = execution::executor::instance().ghost_copies_started();
  execute<average>(lists, density(tree), neighbour_mean(tree));

  // The direct sums over all particles, with the same pair criterion.
  const double R = support * h;
  std::vector<std::vector<std::uint64_t>> near(total);
  std::vector<double> direct(total, 0.0), direct_mean(total, 0.0);
  for (std::uint64_t a = 0; a < total; ++a)
    for (std::uint64_t b = 0; b < total; ++b) {
      const double r2 = distance_squared(position_of(a), position_of(b));
      if (nt::within_radius(r2, R)) near[a].push_back(b), direct[a] += kernel(r2, R) / double(total);
    }
  for (std::uint64_t a = 0; a < total; ++a) {
    for (std::uint64_t b : near[a]) direct_mean[a] += direct[b];
    direct_mean[a] /= double(near[a].size());
  }
  auto id = host_view(tree_type::id(tree));
  auto rho = host_view(density(tree)), mean = host_view(neighbour_mean(tree));
  bool correct = execution::executor::instance().ghost_copies_started() == copies + 1;
  for (std::size_t a = 0; a < tree.owned_size(); ++a) {
    correct &= lists.count(a) == near[id(a)].size();
    correct &= std::abs(rho(a) - direct[id(a)]) <= 1e-12 * direct[id(a)];
    correct &= std::abs(mean(a) - direct_mean[id(a)]) <= 1e-12 * direct_mean[id(a)];
  }
  std::uint64_t owned = tree.owned_size(), owned_total = 0;  // no particle lost or duplicated
  MPI_Allreduce(&owned, &owned_total, 1, MPI_UINT64_T, MPI_SUM, runtime::communicator());
  int all_correct = correct && owned_total == total;
  MPI_Allreduce(MPI_IN_PLACE, &all_correct, 1, MPI_INT, MPI_LAND, runtime::communicator());
  log::info() << total << " particles on " << ranks << " ranks; rank 0: " << tree.owned_size() << " owned, "
              << tree.ghost_size() << " ghosts, " << double(lists.total()) / double(tree.owned_size())
              << " neighbours per particle";
  if (!all_correct) log::error() << "tutorial 5: the tree's sums differ from the direct sums";
  return all_correct ? 0 : 1;
}
