// Branch sharing and ghosts of the ntree topology: every particle within reach of an owned one
// is local (owned or ghost), the local search returns exactly the brute-force neighbours (ids in
// (key, id) order, so the same lists on any rank count), periodic images included; ghosts carry
// their owners' values, are ordered by source rank then (key, id), and ghost copies of any field,
// the built-in ones during distribute() included, go through the executor.
#include <catch2/catch.hpp>

#include "tests/flecsi_lite/topology/ntree/harness.hh"

#include <algorithm>
#include <cmath>
#include <string>

using namespace ntree_mpi_test;

namespace {

template<int D>
struct user_fields {
  static inline const field<double>::definition<nt::ntree<D>> tag{"tag"};
};
double tag_of(std::uint64_t id) { return static_cast<double>(id % 65521) * 0.5 - 7; }

/// The input sorted by (key, id) in the tree's key box: the global order every rank count gives.
template<int D>
particle_set<D> sorted_reference(const particle_set<D>& set, const nt::ntree<D>& tree) {
  particle_set<D> sorted = set;
  sorted.domain = tree.key_box();
  ntree_test::sort_by_key(sorted, tree.settings().order);
  return sorted;
}

/// The first violated ghost property, or an empty string.
template<int D>
std::string ghost_problem(nt::ntree<D>& tree, const particle_set<D>& sorted, const nt::distribution_stats& stats) {
  using topology = nt::ntree<D>;
  const auto x = flecsi_lite::host_view(topology::position(tree));
  const auto id = flecsi_lite::host_view(topology::id(tree));
  const auto m = flecsi_lite::host_view(topology::mass(tree));
  const auto h = flecsi_lite::host_view(topology::smoothing_length(tree));
  const auto key = flecsi_lite::host_view(topology::key(tree));
  const std::size_t owned = tree.owned_size();
  const auto index = index_by_id(sorted);

  // Owner of every particle, from the gathered owned ids.
  std::vector<std::pair<std::uint64_t, int>> mine;
  for (std::size_t i = 0; i < owned; ++i) mine.emplace_back(id(i), rank());
  std::unordered_map<std::uint64_t, int> owner;
  for (const auto& [particle, r] : gather_all(mine)) owner[particle] = r;

  if (stats.exclusive + stats.shared != owned) return "exclusive + shared != owned";
  if (stats.ghosts != tree.ghost_size()) return "ghost count";
  if (size() == 1 && tree.ghost_size() != 0) return "ghosts on a single rank";
  std::size_t sent = 0;
  for (const auto& peer : tree.plan().peers) sent += peer.send.size();
  const auto sent_all = gather_all(std::vector<std::size_t>{sent});
  std::size_t sent_total = 0;
  for (const std::size_t s : sent_all) sent_total += s;
  if (sent_total != stats.ghost_total) return "sent and received ghost counts differ";
  if ((stats.shared == 0) != (sent == 0)) return "shared count inconsistent with the plan";

  int previous_rank = -1;
  for (const auto& peer : tree.plan().peers) {
    if (peer.rank <= previous_rank || peer.rank == rank()) return "plan peers not in rank order";
    previous_rank = peer.rank;
    for (std::size_t k = 0; k < peer.receive_count; ++k) {
      const std::size_t g = owned + peer.receive_first + k;
      const auto found = index.find(id(g));
      if (found == index.end()) return "ghost with unknown id";
      const std::size_t j = found->second;
      if (owner[id(g)] != peer.rank) return "ghost not owned by the rank it came from";
      if (x(g) != sorted.x[j] || h(g) != sorted.h[j] || m(g) != sorted.m[j] || key(g) != sorted.keys[j])
        return "ghost built-in field differs from the owner's value";
      if (k > 0 && !(nt::key_id{key(g - 1), id(g - 1)} < nt::key_id{key(g), id(g)}))
        return "ghosts of one source not in (key, id) order";
    }
  }
  return "";
}

/// Compares the tree's neighbour lists of the owned particles with brute force over all
/// particles (only the rows of this rank's particles are computed): the same ids in the same
/// order, and the same periodic image shifts.
template<int D>
std::string search_problem(nt::ntree<D>& tree, const particle_set<D>& sorted, nt::interaction kind) {
  const auto id = flecsi_lite::host_view(nt::ntree<D>::id(tree));
  const auto index = index_by_id(sorted);
  const std::size_t owned = tree.owned_size();
  std::vector<std::uint8_t> targets(sorted.size(), 0);
  for (std::size_t a = 0; a < owned; ++a) targets[index.at(id(a))] = 1;
  nt::search_options options;
  options.kind = kind;
  options.support = tree.settings().support;
  options.targets = targets.data();
  nt::neighbour_lists reference, found;
  nt::brute_force_neighbours<D>(sorted.x.data(), sorted.h.data(), sorted.size(), tree.space(), options, reference);
  tree.find_neighbours(found, kind);

  if (found.size() != owned) return "one list per owned particle expected";
  const bool periodic = tree.space().any_periodic();
  std::size_t total = 0;
  for (std::size_t a = 0; a < owned; ++a) {
    const std::size_t j = index.at(id(a));
    if (found.count(a) != reference.count(j)) return "neighbour count differs from brute force";
    total += found.count(a);
    for (std::size_t e = 0; e < found.count(a); ++e) {
      const std::size_t b = found.neighbours[found.offsets[a] + e];
      if (b >= tree.total_size()) return "neighbour outside owned and ghost particles";
      if (id(b) != sorted.id[reference.neighbours[reference.offsets[j] + e]])
        return "neighbour ids or their order differ from brute force";
      if (periodic && found.shifts[found.offsets[a] + e] != reference.shifts[reference.offsets[j] + e])
        return "periodic image differs from brute force";
    }
  }
  // The callback form visits the same pairs.
  std::vector<std::size_t> visits(owned, 0);
  tree.for_each_neighbour([&visits](std::size_t a, std::size_t, const nt::point<D>&) { ++visits[a]; }, kind);
  for (std::size_t a = 0; a < owned; ++a)
    if (visits[a] != found.count(a)) return "for_each_neighbour differs from find_neighbours";
  return total > 0 || owned == 0 ? "" : "no neighbours at all: the test would prove nothing";
}

template<int D>
void check_ghosts(particle_set<D> set, start how, const typename nt::ntree<D>::config& config) {
  if (config.fixed_box) {  // periodic inputs live in the box; reach below half the period
    for (auto& x : set.x)
      for (int k = 0; k < D; ++k)
        if (config.periodic[k]) x[k] -= std::floor(x[k]);
    for (auto& h : set.h) h = std::min(h, 0.1);
  }
  nt::ntree<D> tree(config);
  load(tree, set, how);
  const auto stats = tree.distribute();
  const auto sorted = sorted_reference(set, tree);
  std::string problem = ghost_problem(tree, sorted, stats);
  if (problem.empty()) problem = search_problem(tree, sorted, nt::interaction::symmetric);
  if (problem.empty()) problem = search_problem(tree, sorted, nt::interaction::gather);
  INFO("D = " << D << ", " << set.size() << " particles, periodic " << config.periodic[0] << ", start " << int(how)
              << ": " << problem);
  CHECK(problem.empty());
}

template<int D>
typename nt::ntree<D>::config periodic_config(bool all_axes) {
  typename nt::ntree<D>::config config;
  nt::box<D> unit;
  unit.lo.fill(0);
  unit.hi.fill(1);
  config.fixed_box = unit;
  config.periodic[0] = true;
  if (all_axes) config.periodic.fill(true);
  return config;
}

template<int D>
void check_all_inputs() {
  const std::size_t n = 1000;
  const std::vector<particle_set<D>> inputs = {ntree_test::uniform<D>(n, 101),
                                               ntree_test::lattice<D>(D == 1   ? 600
                                                                      : D == 2 ? 30
                                                                               : 9,
                                                                      1.0),
                                               ntree_test::gaussian_blobs<D>(n, 3, 0.06, 102),
                                               ntree_test::coincident<D>(n, 30, 103)};
  typename nt::ntree<D>::config open;
  open.branch_count = 16;  // coarse branches: many shared particles
  for (std::size_t i = 0; i < inputs.size(); ++i) {
    check_ghosts<D>(inputs[i], i % 2 ? start::rank_zero : start::random_ranks, open);
    check_ghosts<D>(inputs[i], start::reversed_blocks, typename nt::ntree<D>::config{});
    check_ghosts<D>(inputs[i], start::random_ranks, periodic_config<D>(true));
    if (D > 1) check_ghosts<D>(inputs[i], start::rank_zero, periodic_config<D>(false));
  }
}

bool position_ghosts_hold(field<nt::point<3>>::accessor<ro, ro> x, field<std::uint64_t>::accessor<ro, ro> id,
                          const particle_set<3>& sorted) {
  const auto index = index_by_id(sorted);
  for (std::size_t g = x.owned_size(); g < x.size(); ++g)
    if (x(g) != sorted.x[index.at(id(g))]) return false;
  return true;
}
void write_tags(field<std::uint64_t>::accessor<ro> id, field<double>::accessor<wo> tag) {
  for (std::size_t i = 0; i < tag.size(); ++i) tag(i) = tag_of(id(i));
}
bool tag_ghosts_hold(field<std::uint64_t>::accessor<ro, ro> id, field<double>::accessor<ro, ro> tag) {
  for (std::size_t g = tag.owned_size(); g < tag.size(); ++g)
    if (tag(g) != tag_of(id(g))) return false;
  return true;
}
void drift(field<nt::point<3>>::accessor<rw> x, field<std::uint64_t>::accessor<ro> id, double step) {
  for (std::size_t i = 0; i < x.size(); ++i)
    for (int k = 0; k < 3; ++k) x(i)[k] += step * std::cos(static_cast<double>(id(i) % 4096) + 2 * k);
}

std::uint64_t copies() { return flecsi_lite::execution::executor::instance().ghost_copies_started(); }

}  // namespace

TEST_CASE("ghosts complete the neighbourhoods of owned particles: 1D") { check_all_inputs<1>(); }
TEST_CASE("ghosts complete the neighbourhoods of owned particles: 2D") { check_all_inputs<2>(); }
TEST_CASE("ghosts complete the neighbourhoods of owned particles: 3D") {
  check_all_inputs<3>();
  typename nt::ntree<3>::config morton;
  morton.order = nt::curve::morton;
  morton.bucket_size = 4;
  check_ghosts<3>(ntree_test::plummer(1500, 104), start::random_ranks, morton);
}

TEST_CASE("ghost copies of any field deliver the owners' values, only when stale") {
  const auto set = ntree_test::gaussian_blobs<3>(1500, 3, 0.07, 201);
  nt::ntree<3> tree;
  load(tree, set, start::rank_zero);
  const auto at_start = copies();
  tree.distribute();
  // The built-in fields' ghosts travel by the executor's copies (the only ghost-copy engine),
  // one per field: position, id, mass, smoothing length, key.
  CHECK(copies() == at_start + 5);
  const auto sorted = sorted_reference(set, tree);
  using topology = nt::ntree<3>;

  // The built-in fields were copied by distribute(): reading their ghosts copies nothing.
  auto before = copies();
  CHECK(
    all_ranks(flecsi_lite::execute<position_ghosts_hold>(topology::position(tree), topology::id(tree), sorted).get()));
  CHECK(copies() == before);

  // A user field: written on owned particles, its ghosts are copied on the first ghost read.
  flecsi_lite::execute<write_tags>(topology::id(tree), user_fields<3>::tag(tree));
  CHECK(all_ranks(flecsi_lite::execute<tag_ghosts_hold>(topology::id(tree), user_fields<3>::tag(tree)).get()));
  CHECK(copies() == before + 1);
  CHECK(all_ranks(flecsi_lite::execute<tag_ghosts_hold>(topology::id(tree), user_fields<3>::tag(tree)).get()));
  CHECK(copies() == before + 1);

  // A new distribution makes the user field's ghosts stale again; the next read copies them.
  before = copies();
  tree.distribute();
  CHECK(copies() == before + 5);
  before = copies();
  CHECK(all_ranks(flecsi_lite::execute<tag_ghosts_hold>(topology::id(tree), user_fields<3>::tag(tree)).get()));
  CHECK(copies() == before + 1);
}

TEST_CASE("after a small drift, refreshing the local tree keeps searches exact") {
  // Ghosts chosen with reach 1.5 * 2h stay sufficient while particles drift far less than h:
  // each distance changes by at most twice the drift.
  const auto set = ntree_test::uniform<3>(1500, 301);
  typename nt::ntree<3>::config config;
  config.ghost_reach_factor = 1.5;
  nt::ntree<3> tree(config);
  load(tree, set, start::random_ranks);
  tree.distribute();
  const double step = 1e-3 * *std::min_element(set.h.begin(), set.h.end());
  const auto before = copies();  // the drift's positions are copied once (eagerly, after it)
  flecsi_lite::execute<drift>(nt::ntree<3>::position(tree), nt::ntree<3>::id(tree), step);
  tree.refresh_local_tree();  // ghost positions are stale: one copy first
  CHECK(copies() == before + 1);

  particle_set<3> moved = set;
  for (std::size_t i = 0; i < moved.size(); ++i)
    for (int k = 0; k < 3; ++k) moved.x[i][k] += step * std::cos(static_cast<double>(moved.id[i] % 4096) + 2 * k);
  // The key box and keys stay those of distribute(); only the order matters for the reference.
  const auto sorted = sorted_reference(set, tree);
  particle_set<3> sorted_moved = sorted;
  const auto index = index_by_id(moved);
  for (std::size_t j = 0; j < sorted.size(); ++j) sorted_moved.x[j] = moved.x[index.at(sorted.id[j])];
  const std::string problem = search_problem(tree, sorted_moved, nt::interaction::symmetric);
  INFO(problem);
  CHECK(problem.empty());
}
