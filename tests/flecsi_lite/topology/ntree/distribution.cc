// Sample-sort distribution of the ntree topology: every particle ends on exactly one rank, the
// ranks hold consecutive runs of the global (key, id) order (the same for any rank count), every
// field follows its particles, and the ranks are balanced by count or by work within the bounds
// of the sampling.
#include <catch2/catch.hpp>

#include "tests/flecsi_lite/topology/ntree/harness.hh"

#include <algorithm>
#include <cmath>
#include <random>
#include <string>

using namespace ntree_mpi_test;

namespace {

/// Fields an application would add: every one must travel with its particle.
struct payload {
  std::uint64_t id_twice;
  float third;
  char letter;
};

template<int D>
struct user_fields {
  static inline const field<double>::definition<nt::ntree<D>> tag{"tag"};
  static inline const field<payload>::definition<nt::ntree<D>> extra{"extra"};
  static inline const field<double>::definition<nt::ntree<D>> weight{"weight"};
};

double tag_of(std::uint64_t id) { return std::sqrt(static_cast<double>(id % 1000003)) + 0.25; }
payload payload_of(std::uint64_t id) {
  return {2 * id, static_cast<float>(id % 97) / 3.0f, static_cast<char>('a' + id % 26)};
}

template<int D>
void set_user_fields(field<std::uint64_t>::accessor<ro> id, field<double>::accessor<wo> tag,
                     field<payload>::accessor<wo> extra) {
  for (std::size_t i = 0; i < id.size(); ++i) {
    tag(i) = tag_of(id(i));
    extra(i) = payload_of(id(i));
  }
}

template<int D>
void move_particles(typename field<nt::point<D>>::template accessor<rw> x, field<std::uint64_t>::accessor<ro> id) {
  for (std::size_t i = 0; i < x.size(); ++i)
    for (int k = 0; k < D; ++k) x(i)[k] += 0.05 * std::sin(static_cast<double>(id(i) % 1000) + k);
}

template<int D>
void neighbour_counts_as_weights(typename flecsi_lite::tracked<nt::local_tree<D>>::template accessor<rw> local,
                                 double support, nt::domain<D> space, field<double>::accessor<wo> weight) {
  nt::neighbour_lists lists;
  local->find_neighbours(nt::interaction::symmetric, support, space, lists);
  for (std::size_t a = 0; a < weight.size(); ++a) weight(a) = static_cast<double>(lists.count(a));
}

/// The first violated property of a distribution of `set` (whose positions may have moved
/// since), or an empty string. Checks, on every rank with gathered data: each particle once,
/// global (key, id) order equal to the sorted input, built-in and user fields attached.
template<int D>
std::string distribution_problem(nt::ntree<D>& tree, const particle_set<D>& set, bool with_user_fields) {
  using topology = nt::ntree<D>;
  const auto x = flecsi_lite::host_view(topology::position(tree));
  const auto id = flecsi_lite::host_view(topology::id(tree));
  const auto m = flecsi_lite::host_view(topology::mass(tree));
  const auto h = flecsi_lite::host_view(topology::smoothing_length(tree));
  const auto key = flecsi_lite::host_view(topology::key(tree));
  const std::size_t n = tree.owned_size();
  const auto index = index_by_id(set);

  std::string problem;
  if (tree.ghost_size() != 0 && size() == 1 && !tree.space().any_periodic()) problem = "ghosts on one rank";
  for (std::size_t i = 0; i < n && problem.empty(); ++i) {
    const auto found = index.find(id(i));
    if (found == index.end()) {
      problem = "unknown id";
      break;
    }
    const std::size_t j = found->second;
    if (m(i) != set.m[j] || h(i) != set.h[j]) problem = "mass or h detached from its particle";
    if (key(i) != nt::key_of<D>(tree.settings().order, tree.key_box(), x(i))) problem = "stale key";
    if (with_user_fields) {
      const auto tag = flecsi_lite::host_view(user_fields<D>::tag(tree));
      const auto extra = flecsi_lite::host_view(user_fields<D>::extra(tree));
      const payload expected = payload_of(id(i));
      if (tag(i) != tag_of(id(i)) || extra(i).id_twice != expected.id_twice || extra(i).third != expected.third ||
          extra(i).letter != expected.letter)
        problem = "user field detached from its particle";
    }
  }
  // The key box is the same everywhere, so the expected order can be computed on every rank.
  std::vector<nt::key_id> mine(n);
  std::vector<nt::point<D>> positions(n);
  for (std::size_t i = 0; i < n; ++i) {
    mine[i] = {key(i), id(i)};
    positions[i] = x(i);
  }
  const auto boxes = gather_all(std::vector<nt::box<D>>{tree.key_box()});
  for (const auto& b : boxes)
    if (b != boxes[0]) problem = "key boxes differ between ranks";
  const auto global = gather_all(mine);
  const auto all_positions = gather_all(positions);
  // Positions may have moved: each particle's key comes from its current (gathered) position.
  std::vector<nt::key_id> expected(set.size());
  for (std::size_t i = 0; i < set.size(); ++i) expected[i] = {0, set.id[i]};
  if (global.size() != set.size()) return problem.empty() ? "particles lost or duplicated" : problem;
  for (std::size_t g = 0; g < global.size(); ++g) {
    const auto found = index.find(global[g].id);
    if (found == index.end()) return "unknown id";
    expected[found->second].key = nt::key_of<D>(tree.settings().order, tree.key_box(), all_positions[g]);
  }
  std::sort(expected.begin(), expected.end());
  if (!(global == expected)) problem = "global order is not the sorted (key, id) order of the input";
  std::size_t before = 0;
  const auto counts = gather_all(std::vector<std::size_t>{n});
  for (int r = 0; r < rank(); ++r) before += counts[r];
  if (tree.first_global_index() != before) problem = "first_global_index";
  if (tree.global_size() != set.size()) problem = "global_size";
  return problem;
}

template<int D>
void check_distribution(const particle_set<D>& set, start how, nt::curve order) {
  typename nt::ntree<D>::config config;
  config.order = order;
  nt::ntree<D> tree(config);
  load(tree, set, how);
  flecsi_lite::execute<set_user_fields<D>>(nt::ntree<D>::id(tree), user_fields<D>::tag(tree),
                                           user_fields<D>::extra(tree));
  const auto stats = tree.distribute();
  const std::string problem = distribution_problem(tree, set, true);
  INFO("D = " << D << ", start " << int(how) << ", " << set.size() << " particles: " << problem);
  CHECK(problem.empty());
  // All samples fit the default budget: the cuts are exact, within one particle of N / P.
  const double ideal = static_cast<double>(set.size()) / size();
  CHECK(std::abs(static_cast<double>(tree.owned_size()) - ideal) <= 1.0);
  CHECK(stats.global_count == set.size());
  CHECK(stats.owned_max <= ideal + 1);
  CHECK(stats.count_imbalance == Approx(set.size() == 0 ? 1.0 : stats.owned_max / ideal));
  CHECK(stats.owned == stats.exclusive + stats.shared);
  CHECK(stats.bytes_per_particle == sizeof(nt::point<D>) + 4 * 8 + sizeof(double) + sizeof(payload));
}

template<int D>
void check_all_inputs() {
  const std::vector<particle_set<D>> inputs = {ntree_test::uniform<D>(1500, 11),
                                               ntree_test::lattice<D>(D == 1   ? 1000
                                                                      : D == 2 ? 32
                                                                               : 11,
                                                                      1.3),
                                               ntree_test::gaussian_blobs<D>(1500, 3, 0.05, 12),
                                               ntree_test::coincident<D>(1200, 40, 13)};
  for (const auto& set : inputs) {
    check_distribution<D>(set, start::rank_zero, nt::curve::hilbert);
    check_distribution<D>(set, start::random_ranks, nt::curve::morton);
    check_distribution<D>(set, start::reversed_blocks, nt::curve::hilbert);
  }
}

}  // namespace

TEST_CASE("regular samples weigh their runs; splitters cut at the nearest sample boundary") {
  std::vector<nt::key_id> sorted;
  for (std::uint64_t i = 0; i < 10; ++i) sorted.push_back({100 + i, i});
  const auto samples = nt::regular_sample(sorted.data(), nullptr, 10, 4);
  REQUIRE(samples.size() == 4);
  CHECK(samples[0].first == sorted[0]);
  CHECK(samples[1].first == sorted[2]);
  CHECK(samples[2].first == sorted[5]);
  CHECK(samples[3].first == sorted[7]);
  CHECK(samples[0].weight + samples[1].weight + samples[2].weight + samples[3].weight == 10);

  // Weights 5, 1, 1, 1 (given out of order): half of 8 is nearest to boundary 1 (5 before it).
  std::vector<nt::sample_entry> weighted = {{{3, 0}, 1}, {{1, 0}, 5}, {{4, 0}, 1}, {{2, 0}, 1}};
  auto cut = nt::choose_splitters(weighted, 2);
  REQUIRE(cut.size() == 1);
  CHECK(cut[0].after_all == 0);
  CHECK(cut[0].first == nt::key_id{2, 0});

  // More parts than samples: the cuts never decrease and the last ones are past all particles.
  cut = nt::choose_splitters({{{7, 1}, 1}}, 4);
  REQUIRE(cut.size() == 3);
  CHECK(cut[0].after_all == 0);
  CHECK(cut[1].after_all == 1);
  CHECK(cut[2].after_all == 1);
  const auto bounds = nt::split_sorted(sorted.data(), 10, cut);
  CHECK(bounds == std::vector<std::size_t>{0, 0, 10, 10, 10});

  // All weights zero: the sample count is balanced instead.
  cut = nt::choose_splitters({{{1, 0}, 0}, {{2, 0}, 0}, {{3, 0}, 0}, {{4, 0}, 0}}, 2);
  CHECK(cut[0].first == nt::key_id{3, 0});
}

TEST_CASE("merging sorted runs gives the (key, id) order of a full sort") {
  std::mt19937_64 random(5);
  for (const std::size_t runs : {1, 2, 3, 7}) {
    // Runs of random (key, id) pairs, each sorted, with equal keys across runs.
    std::vector<nt::key_type> keys;
    std::vector<std::uint64_t> ids;
    std::vector<std::size_t> starts;
    for (std::size_t r = 0; r < runs; ++r) {
      starts.push_back(keys.size());
      std::vector<nt::key_id> run(random() % 50);
      for (auto& p : run) p = {random() % 20, random()};
      std::sort(run.begin(), run.end());
      for (const auto& p : run) {
        keys.push_back(p.key);
        ids.push_back(p.id);
      }
    }
    std::vector<std::size_t> merged;
    nt::merge_sorted_runs(keys.data(), ids.data(), keys.size(), starts, merged);
    CHECK(merged == nt::sort_permutation(keys.data(), ids.data(), keys.size()));
  }
}

TEST_CASE("every particle on one rank, in global (key, id) order, with all its fields: 1D") { check_all_inputs<1>(); }
TEST_CASE("every particle on one rank, in global (key, id) order, with all its fields: 2D") { check_all_inputs<2>(); }
TEST_CASE("every particle on one rank, in global (key, id) order, with all its fields: 3D") {
  check_all_inputs<3>();
  check_distribution<3>(ntree_test::plummer(1500, 14), start::random_ranks, nt::curve::hilbert);
}

TEST_CASE("few, no and coincident particles") {
  for (std::size_t n : {0, 1, 3, 5})
    check_distribution<2>(ntree_test::uniform<2>(n, 21), start::rank_zero, nt::curve::hilbert);
  // Every particle at one point: a degenerate bounding box, keys all equal, ids decide.
  auto same = ntree_test::uniform<3>(700, 22);
  for (auto& x : same.x) x = {0.5, 0.5, 0.5};
  check_distribution<3>(same, start::random_ranks, nt::curve::morton);
}

TEST_CASE("particles that moved are redistributed with their fields") {
  const auto set = ntree_test::gaussian_blobs<3>(1500, 4, 0.08, 31);
  nt::ntree<3> tree;
  load(tree, set, start::random_ranks);
  flecsi_lite::execute<set_user_fields<3>>(nt::ntree<3>::id(tree), user_fields<3>::tag(tree),
                                           user_fields<3>::extra(tree));
  tree.distribute();
  for (int round = 0; round < 2; ++round) {
    flecsi_lite::execute<move_particles<3>>(nt::ntree<3>::position(tree), nt::ntree<3>::id(tree));
    const auto stats = tree.distribute();
    const std::string problem = distribution_problem(tree, set, true);
    INFO(problem);
    CHECK(problem.empty());
    CHECK(stats.owned_max <= static_cast<double>(set.size()) / size() + 1);
  }
}

TEST_CASE("a small sample keeps the count imbalance within the sampling bound") {
  // With s_r samples of n_r sorted particles, a sample stands for at most w_r = ceil(n_r / s_r)
  // particles; a cut's estimated rank misses the true one by at most the sum of the w_r (one
  // straddling run per rank) and lies within max w_r / 2 of its target, so every rank holds
  // N / P within max w_r + 2 sum w_r.
  const auto set = ntree_test::uniform<3>(3000, 41);
  for (start how : {start::rank_zero, start::random_ranks}) {
    typename nt::ntree<3>::config config;
    config.sample_bytes = 64 * sizeof(nt::key_type);  // 64 samples per rank
    nt::ntree<3> tree(config);
    load(tree, set, how);
    const auto initial = gather_all(std::vector<std::size_t>{tree.owned_size()});
    double widest = 0, sum = 0;
    for (const std::size_t n_r : initial) {
      const double w = n_r ? std::ceil(static_cast<double>(n_r) / std::min<double>(n_r, 64)) : 0;
      widest = std::max(widest, w);
      sum += w;
    }
    const auto stats = tree.distribute();
    const double ideal = 3000.0 / size();
    INFO("bound " << widest + 2 * sum << ", imbalance " << stats.count_imbalance);
    CHECK(std::abs(static_cast<double>(tree.owned_size()) - ideal) <= widest + 2 * sum);
    CHECK(distribution_problem(tree, set, false).empty());
  }
}

TEST_CASE("balancing by work evens the summed weights") {
  // Clustered particles have very different neighbour counts; the first distribution (all
  // weights zero) balances counts, the second the neighbour counts it measured. With every
  // particle a sample, each rank's work is within the largest single weight of W / P.
  const auto set = ntree_test::gaussian_blobs<3>(2000, 2, 0.04, 51, 60);
  typename nt::ntree<3>::config config;
  config.balancing = nt::balance::work;
  config.work_weight = &user_fields<3>::weight;
  nt::ntree<3> tree(config);
  load(tree, set, start::rank_zero);
  const auto by_count = tree.distribute();
  CHECK(by_count.owned_max <= 2000.0 / size() + 1);
  flecsi_lite::execute<neighbour_counts_as_weights<3>>(tree.local_tree_object(), tree.settings().support, tree.space(),
                                                       user_fields<3>::weight(tree))
    .wait();
  double local_max = 0;
  {
    const auto w = flecsi_lite::host_view(user_fields<3>::weight(tree));
    for (std::size_t i = 0; i < tree.owned_size(); ++i) local_max = std::max(local_max, w(i));
  }
  double largest_weight = 0;
  MPI_Allreduce(&local_max, &largest_weight, 1, MPI_DOUBLE, MPI_MAX, flecsi_lite::runtime::communicator());
  const auto by_work = tree.distribute();
  const auto w = flecsi_lite::host_view(user_fields<3>::weight(tree));
  double work = 0;
  for (std::size_t i = 0; i < tree.owned_size(); ++i) work += w(i);
  INFO("work per rank " << work << ", mean " << by_work.work_mean << ", largest weight " << largest_weight
                        << ", work imbalance by count " << by_count.work_imbalance << ", by work "
                        << by_work.work_imbalance);
  CHECK(by_work.work == work);
  CHECK(std::abs(work - by_work.work_mean) <= largest_weight);
  CHECK(by_work.work_imbalance <= 1 + largest_weight / by_work.work_mean);
  CHECK(distribution_problem(tree, set, false).empty());
}

TEST_CASE("fields present on some ranks only are refused on every rank") {
  if (size() < 2) return;
  static const field<int>::definition<nt::ntree<1>> lonely{"lonely"};
  nt::ntree<1> tree;
  load(tree, ntree_test::uniform<1>(100, 61), start::random_ranks);
  if (rank() == 0) flecsi_lite::host_view(lonely(tree));
  CHECK_THROWS_WITH(tree.distribute(), Catch::Contains("some ranks only"));
}
