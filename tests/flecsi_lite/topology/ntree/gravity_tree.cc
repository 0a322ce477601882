// Rank invariance of the distributed gravity tree (locally essential trees): accelerations and
// potentials on 1 to 4 ranks bitwise equal to one rank, for uneven splits in key order through a
// stack of coincident particles, an empty rank, leaves spanning ranks, both opening criteria, and
// equal to direct summation at theta = 0; imports are needed (the local tree alone is wrong).
#include <catch2/catch.hpp>

#include "flecsi_lite/runtime/context.hh"
#include "flecsi_lite/topology/ntree.hh"
#include "flecsi_lite/topology/ntree/gravity/direct_gravity.hh"
#include "tests/flecsi_lite/topology/ntree/gravity_sets.hh"
#include "tests/flecsi_lite/topology/ntree/harness.hh"
#include "tests/flecsi_lite/topology/ntree/particle_sets.hh"

#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <iostream>
#include <vector>

namespace {

namespace nt = flecsi_lite::topology::ntree;
using ntree_test::particle_set;

MPI_Comm world() { return flecsi_lite::runtime::communicator(); }
int rank() { return flecsi_lite::runtime::rank(); }
int ranks() { return flecsi_lite::runtime::size(); }

/// A non-uniform set sorted by (key, id) whose last `stack` particles sit on particle 0 (more
/// than a bucket at the deepest level, so a leaf of coincident particles).
template<int D>
particle_set<D> with_stack(particle_set<D> set, std::size_t stack) {
  for (std::size_t i = set.size() - stack; i < set.size(); ++i) set.x[i] = set.x[0];
  ntree_test::sort_by_key(set, nt::curve::hilbert);
  return set;
}

/// Rank boundaries in the sorted set: uneven, the first cut through the middle of the
/// coincident stack, and on 4 ranks an empty rank.
template<int D>
std::vector<std::size_t> rank_bounds(const particle_set<D>& set, std::size_t through_stack) {
  const std::size_t n = set.size();
  std::vector<std::size_t> cuts;
  if (ranks() == 2) cuts = {through_stack};
  if (ranks() == 3) cuts = {through_stack, n * 23 / 100};
  if (ranks() == 4) cuts = {through_stack, n * 61 / 100, n * 61 / 100};
  REQUIRE(cuts.size() == static_cast<std::size_t>(ranks() - 1));
  std::sort(cuts.begin(), cuts.end());
  cuts.insert(cuts.begin(), 0);
  cuts.push_back(n);
  return cuts;
}

/// The sorted index of the middle of the coincident stack: the longest run of equal keys.
template<int D>
std::size_t stack_middle(const particle_set<D>& set) {
  std::size_t best_first = 0, best_length = 0;
  for (std::size_t first = 0, last = 0; first < set.size(); first = last) {
    for (last = first; last < set.size() && set.keys[last] == set.keys[first];) ++last;
    if (last - first > best_length) {
      best_first = first;
      best_length = last - first;
    }
  }
  return best_first + best_length / 2;
}

template<int D>
struct field_result {
  std::vector<nt::point<D>> a;
  std::vector<double> phi;
  std::size_t imported_nodes = 0, imported_particles = 0, top_nodes = 0, sent_groups = 0, groups = 0;
};

/// The gravity tree over particles [first, last) of the sorted set on `comm`, evaluated.
template<int D, class Near>
field_result<D> run(const particle_set<D>& set, std::size_t first, std::size_t last, const double* acceleration_old,
                    const nt::gravity_options& options, const Near& near, MPI_Comm comm) {
  nt::gravity_tree<D> tree;
  const std::size_t n = last - first;
  tree.build(set.keys.data() + first, set.x.data() + first, set.m.data() + first, set.h.data() + first,
             acceleration_old ? acceleration_old + first : nullptr, n, options, comm);
  field_result<D> result;
  result.a.resize(n);
  result.phi.resize(n);
  tree.evaluate(near, result.a.data(), result.phi.data());
  result.imported_nodes = tree.imported_nodes();
  result.imported_particles = tree.imported_particles();
  result.top_nodes = tree.top_nodes();
  result.sent_groups = tree.sent_groups();
  result.groups = tree.groups().size();
  return result;
}

/// Every rank's `mine` concatenated in rank order.
template<class T>
std::vector<T> gather(const std::vector<T>& mine) {
  int bytes = static_cast<int>(mine.size() * sizeof(T));
  std::vector<int> counts(ranks()), offsets(ranks());
  MPI_Allgather(&bytes, 1, MPI_INT, counts.data(), 1, MPI_INT, world());
  int total = 0;
  for (int r = 0; r < ranks(); ++r) {
    offsets[r] = total;
    total += counts[r];
  }
  std::vector<T> all(static_cast<std::size_t>(total) / sizeof(T));
  MPI_Allgatherv(mine.data(), bytes, MPI_BYTE, all.data(), counts.data(), offsets.data(), MPI_BYTE, world());
  return all;
}

template<int D>
double norm(const nt::point<D>& a) {
  return std::sqrt(nt::distance_squared<D>(a, nt::point<D>{}));
}

/// Largest relative difference of b from a (accelerations by vector norm), 0 when bitwise equal.
template<int D>
double largest_difference(const field_result<D>& a, const field_result<D>& b) {
  double worst = 0;
  for (std::size_t i = 0; i < a.a.size(); ++i) {
    nt::point<D> d;
    for (int k = 0; k < D; ++k) d[k] = a.a[i][k] - b.a[i][k];
    worst = std::max(worst, norm<D>(d) / norm<D>(a.a[i]));
    worst = std::max(worst, std::abs(a.phi[i] - b.phi[i]) / std::abs(a.phi[i]));
  }
  return worst;
}

/// Runs the set split over the ranks and on one rank; checks the gathered fields are the same
/// bits and reports what the ranks imported. Returns the one-rank result.
template<int D, class Near>
field_result<D> check_rank_invariance(const particle_set<D>& set, const std::vector<std::size_t>& bounds,
                                      const double* acceleration_old, const nt::gravity_options& options,
                                      const Near& near, const char* what) {
  const std::size_t first = bounds[rank()], last = bounds[rank() + 1];
  const field_result<D> mine = run<D>(set, first, last, acceleration_old, options, near, world());
  const field_result<D> one = run<D>(set, 0, set.size(), acceleration_old, options, near, MPI_COMM_SELF);
  field_result<D> all;
  all.a = gather(mine.a);
  all.phi = gather(mine.phi);
  REQUIRE(all.a.size() == set.size());
  const bool same = std::memcmp(all.a.data(), one.a.data(), all.a.size() * sizeof(nt::point<D>)) == 0 &&
                    std::memcmp(all.phi.data(), one.phi.data(), all.phi.size() * sizeof(double)) == 0;
  INFO(what << " on " << ranks() << " ranks: largest relative difference from one rank "
            << largest_difference<D>(one, all));
  CHECK(same);
  const auto nodes = gather(std::vector<std::size_t>{mine.imported_nodes});
  const auto particles = gather(std::vector<std::size_t>{mine.imported_particles});
  const auto owned = gather(std::vector<std::size_t>{last - first});
  const auto groups = gather(std::vector<std::size_t>{mine.groups});
  const auto sent = gather(std::vector<std::size_t>{mine.sent_groups});
  if (rank() == 0 && ranks() > 1) {
    std::cout << what << ", " << ranks() << " ranks, top tree " << mine.top_nodes << " nodes; per rank (owned / "
              << "imported nodes / imported particles / groups / group records sent):";
    for (int r = 0; r < ranks(); ++r)
      std::cout << " " << owned[r] << "/" << nodes[r] << "/" << particles[r] << "/" << groups[r] << "/" << sent[r];
    std::cout << "\n";
  }
  // Every non-empty rank needs something from the others.
  if (ranks() > 1 && last > first && last - first < set.size())
    CHECK(mine.imported_nodes + mine.imported_particles > 0);
  return one;
}

}  // namespace

TEST_CASE("distributed gravity: Evrard sphere with a coincident stack, bitwise equal on any rank count") {
  const auto set = with_stack<3>(ntree_test::evrard_sphere(20000, 7), 60);
  const auto bounds = rank_bounds<3>(set, stack_middle<3>(set));
  const ntree_test::spline_pair near;

  nt::gravity_options options;  // theta 0.5, quadrupoles, bucket 16, groups of 32
  const auto geometric = check_rank_invariance<3>(set, bounds, nullptr, options, near, "theta 0.5");

  // GADGET-2's relative criterion with the old accelerations of the geometric pass.
  std::vector<double> acceleration_old(set.size());
  for (std::size_t i = 0; i < set.size(); ++i) acceleration_old[i] = norm<3>(geometric.a[i]);
  nt::gravity_options relative = options;
  relative.relative_criterion = true;
  relative.theta = 0.7;
  check_rank_invariance<3>(set, bounds, acceleration_old.data(), relative, near, "relative criterion");

  nt::gravity_options monopole = options;
  monopole.quadrupole = false;
  monopole.theta = 0.7;
  monopole.group_size = 8;
  check_rank_invariance<3>(set, bounds, nullptr, monopole, near, "monopoles, theta 0.7, groups of 8");

  // Leaves (and groups) far larger than a rank's share near the stack: they span ranks.
  nt::gravity_options wide = options;
  wide.bucket_size = 3000;
  wide.group_size = 4000;
  check_rank_invariance<3>(set, bounds, nullptr, wide, near, "leaves of 3000 spanning ranks");
}

TEST_CASE("distributed gravity: the imports are needed") {
  const auto set = with_stack<3>(ntree_test::plummer(8000, 3), 40);
  const auto bounds = rank_bounds<3>(set, stack_middle<3>(set));
  const std::size_t first = bounds[rank()], last = bounds[rank() + 1];
  nt::gravity_options options;
  nt::gravity_tree<3> tree;
  tree.build(set.keys.data() + first, set.x.data() + first, set.m.data() + first, set.h.data() + first, nullptr,
             last - first, options, world());
  const std::size_t n = last - first;
  std::vector<nt::point<3>> a(n), a_local(n);
  std::vector<double> phi(n), phi_local(n);
  const ntree_test::spline_pair near;
  tree.evaluate(near, a.data(), phi.data());
  // The same groups walked on this rank's own tree only: without the top tree and the imported
  // nodes and particles the field misses the other ranks' mass.
  nt::gravity_targets<3> targets;
  targets.x = set.x.data() + first;
  targets.h = set.h.data() + first;
  nt::gravity_walk<3>(nt::gravity_sources_of<3>(tree.local_tree()), tree.groups(), targets, options, near,
                      a_local.data(), phi_local.data());
  if (ranks() > 1 && n > 0) {
    CHECK(tree.imported_nodes() > 0);
    double worst = 0;
    for (std::size_t i = 0; i < n; ++i) worst = std::max(worst, std::abs(phi[i] - phi_local[i]) / std::abs(phi[i]));
    INFO("largest relative potential change without imports: " << worst);
    CHECK(worst > 1e-3);
  } else if (ranks() == 1) {
    // One rank: the local tree is the whole tree.
    CHECK(tree.imported_nodes() == 0);
    CHECK(std::memcmp(a.data(), a_local.data(), n * sizeof(nt::point<3>)) == 0);
    CHECK(std::memcmp(phi.data(), phi_local.data(), n * sizeof(double)) == 0);
  }
}

TEST_CASE("distributed gravity: one rank's groups are target_groups of the hashed tree") {
  const auto set = with_stack<3>(ntree_test::plummer(5000, 4), 40);
  nt::gravity_options options;
  std::vector<double> acceleration_old(set.size());
  for (std::size_t i = 0; i < set.size(); ++i) acceleration_old[i] = 1 + static_cast<double>(i % 7);
  nt::gravity_tree<3> tree;
  tree.build(set.keys.data(), set.x.data(), set.m.data(), set.h.data(), acceleration_old.data(), set.size(), options,
             MPI_COMM_SELF);
  auto mine = tree.groups();
  auto expected = nt::target_groups<3>(tree.local_tree(), options.group_size, acceleration_old.data());
  const auto by_begin = [](const nt::target_group<3>& a, const nt::target_group<3>& b) { return a.begin < b.begin; };
  std::sort(mine.begin(), mine.end(), by_begin);
  std::sort(expected.begin(), expected.end(), by_begin);
  REQUIRE(mine.size() == expected.size());
  for (std::size_t g = 0; g < mine.size(); ++g) {
    CHECK(mine[g].begin == expected[g].begin);
    CHECK(mine[g].end == expected[g].end);
    CHECK(mine[g].bounds == expected[g].bounds);
    CHECK(mine[g].h_max == expected[g].h_max);
    CHECK(mine[g].acceleration_min == expected[g].acceleration_min);
  }
}

TEST_CASE("distributed gravity: theta = 0 is direct summation on any rank count") {
  const auto set = with_stack<3>(ntree_test::plummer(3000, 5), 30);
  const auto bounds = rank_bounds<3>(set, stack_middle<3>(set));
  const ntree_test::spline_pair near;
  std::vector<nt::point<3>> a_direct(set.size());
  std::vector<double> phi_direct(set.size());
  nt::direct_gravity<3>(set.x.data(), set.m.data(), set.h.data(), set.size(), near, a_direct.data(), phi_direct.data());
  nt::gravity_options every_node;
  every_node.theta = 0;
  // The relative criterion with alpha = 0 accepts no node either.
  nt::gravity_options relative_zero;
  relative_zero.relative_criterion = true;
  relative_zero.relative_tolerance = 0;
  std::vector<double> acceleration_old(set.size(), 1.0);
  for (const auto* options : {&every_node, &relative_zero}) {
    const auto one =
      check_rank_invariance<3>(set, bounds, options == &relative_zero ? acceleration_old.data() : nullptr, *options,
                               near, options == &every_node ? "theta 0" : "alpha 0");
    double worst_a = 0, worst_phi = 0;
    for (std::size_t i = 0; i < set.size(); ++i) {
      nt::point<3> d;
      for (int k = 0; k < 3; ++k) d[k] = one.a[i][k] - a_direct[i][k];
      worst_a = std::max(worst_a, norm<3>(d) / norm<3>(a_direct[i]));
      worst_phi = std::max(worst_phi, std::abs(one.phi[i] - phi_direct[i]) / std::abs(phi_direct[i]));
    }
    INFO("largest relative differences from direct summation: acceleration " << worst_a << ", potential " << worst_phi);
    CHECK(worst_a < 1e-10);
    CHECK(worst_phi < 1e-12);
  }
}

TEST_CASE("distributed gravity in 1 and 2 dimensions: bitwise equal on any rank count") {
  const ntree_test::spline_pair near;
  nt::gravity_options options;
  const auto blobs = with_stack<2>(ntree_test::gaussian_blobs<2>(4000, 3, 0.05, 9), 30);
  check_rank_invariance<2>(blobs, rank_bounds<2>(blobs, stack_middle<2>(blobs)), nullptr, options, near,
                           "2D Gaussian blobs");
  const auto line = with_stack<1>(ntree_test::gaussian_blobs<1>(2000, 2, 0.05, 10), 30);
  check_rank_invariance<1>(line, rank_bounds<1>(line, stack_middle<1>(line)), nullptr, options, near,
                           "1D Gaussian blobs");
}

TEST_CASE("distributed gravity on particles distributed by the ntree: bitwise equal to one rank") {
  // The ntree's sample sort decides the split and the keys (its key box and Hilbert order).
  auto set = ntree_test::plummer(6000, 8);
  for (std::size_t i = set.size() - 40; i < set.size(); ++i) set.x[i] = set.x[1];
  nt::ntree<3> particles;
  ntree_mpi_test::load(particles, set, ntree_mpi_test::start::random_ranks);
  particles.distribute();
  using topology = nt::ntree<3>;
  const auto x = flecsi_lite::host_view(topology::position(particles));
  const auto m = flecsi_lite::host_view(topology::mass(particles));
  const auto h = flecsi_lite::host_view(topology::smoothing_length(particles));
  const auto key = flecsi_lite::host_view(topology::key(particles));
  const std::size_t n = particles.owned_size();
  particle_set<3> mine;
  for (std::size_t i = 0; i < n; ++i) {
    mine.x.push_back(x(i));
    mine.m.push_back(m(i));
    mine.h.push_back(h(i));
    mine.keys.push_back(key(i));
  }
  // All ranks' owned particles in rank order: the global (key, id) order, for the one-rank tree.
  particle_set<3> all;
  all.x = gather(mine.x);
  all.m = gather(mine.m);
  all.h = gather(mine.h);
  all.keys = gather(mine.keys);
  REQUIRE(all.size() == set.size());
  const ntree_test::spline_pair near;
  nt::gravity_options options;
  const field_result<3> here = run<3>(mine, 0, n, nullptr, options, near, world());
  const field_result<3> one = run<3>(all, 0, all.size(), nullptr, options, near, MPI_COMM_SELF);
  const auto a = gather(here.a);
  const auto phi = gather(here.phi);
  CHECK(std::memcmp(a.data(), one.a.data(), a.size() * sizeof(nt::point<3>)) == 0);
  CHECK(std::memcmp(phi.data(), one.phi.data(), phi.size() * sizeof(double)) == 0);
}

TEST_CASE("distributed gravity: all particles on the last rank, and no particles at all") {
  const auto set = with_stack<3>(ntree_test::plummer(3000, 6), 30);
  std::vector<std::size_t> bounds(static_cast<std::size_t>(ranks()), 0);
  bounds.push_back(set.size());
  const ntree_test::spline_pair near;
  check_rank_invariance<3>(set, bounds, nullptr, nt::gravity_options{}, near, "all on the last rank");

  nt::gravity_tree<3> none;
  none.build(nullptr, nullptr, nullptr, nullptr, nullptr, 0, nt::gravity_options{}, world());
  CHECK(none.groups().empty());
  CHECK(none.evaluate(near, nullptr, nullptr).node_interactions == 0);
}
