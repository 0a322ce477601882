// Benchmark of the local ntree topology: keys, (key, id) sort and tree build per particle for
// 1e5 and 1e6 particles, and neighbour searches (group walk, per-target walk, uniform cell list,
// brute force) on the same data, reported as times per particle and ratios from one run.
#include "flecsi_lite/topology/ntree/reference/brute_force.hh"
#include "flecsi_lite/topology/ntree/reference/cell_list.hh"
#include "flecsi_lite/topology/ntree/search/group_walk.hh"
#include "flecsi_lite/topology/ntree/search/radius_search.hh"
#include "flecsi_lite/topology/ntree/sfc/keys.hh"
#include "flecsi_lite/topology/ntree/sfc/ordering.hh"
#include "flecsi_lite/topology/ntree/tree/hashed_tree.hh"
#include "tests/flecsi_lite/topology/ntree/particle_sets.hh"

#include <Kokkos_Core.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <functional>
#include <string>
#include <typeinfo>
#include <vector>

namespace nt = flecsi_lite::topology::ntree;
using ntree_test::particle_set;

namespace {

// Best of `repeats` wall-clock times of `work`, in seconds.
double best_time(int repeats, const std::function<void()>& work) {
  double best = 1e300;
  for (int r = 0; r < repeats; ++r) {
    const auto start = std::chrono::steady_clock::now();
    work();
    const auto stop = std::chrono::steady_clock::now();
    best = std::min(best, std::chrono::duration<double>(stop - start).count());
  }
  return best;
}

double per_particle_ns(double seconds, std::size_t n) { return 1e9 * seconds / static_cast<double>(n); }

particle_set<3> make_set(const std::string& kind, std::size_t n, double neighbours) {
  if (kind == "uniform") return ntree_test::uniform<3>(n, 1, neighbours, 0.0);
  return ntree_test::plummer(n, 2, neighbours);
}

// Keys, sort, permutation and tree build of n particles of the given kind.
void build_row(const std::string& kind, std::size_t n, int repeats) {
  particle_set<3> set = make_set(kind, n, 60);
  std::vector<nt::key_type> keys(n), sorted_keys(n);
  std::vector<std::size_t> permutation;
  std::vector<nt::point<3>> x(n);
  std::vector<double> m(n), h(n);
  std::vector<std::uint64_t> id(n);

  const double morton =
    best_time(repeats, [&] { nt::compute_keys<3>(nt::curve::morton, set.domain, set.x.data(), n, keys.data()); });
  const double hilbert =
    best_time(repeats, [&] { nt::compute_keys<3>(nt::curve::hilbert, set.domain, set.x.data(), n, keys.data()); });
  const double sort = best_time(repeats, [&] { nt::sort_permutation(keys.data(), set.id.data(), n, permutation); });
  const double permute = best_time(repeats, [&] {
    nt::apply_permutation(permutation, keys.data(), sorted_keys.data());
    nt::apply_permutation(permutation, set.x.data(), x.data());
    nt::apply_permutation(permutation, set.m.data(), m.data());
    nt::apply_permutation(permutation, set.h.data(), h.data());
    nt::apply_permutation(permutation, set.id.data(), id.data());
  });
  nt::hashed_tree<3> tree;
  const double build = best_time(repeats, [&] {
    tree.build(sorted_keys.data(), x.data(), m.data(), h.data(), n, {16, false});
  });
  const double build_quadrupole = best_time(repeats, [&] {
    tree.build(sorted_keys.data(), x.data(), m.data(), h.data(), n, {16, true});
  });
  const double bytes_quadrupole = static_cast<double>(tree.bytes()) / static_cast<double>(n);
  tree.build(sorted_keys.data(), x.data(), m.data(), h.data(), n, {16, false});
  const double bytes = static_cast<double>(tree.bytes()) / static_cast<double>(n);
  const double total = hilbert + sort + permute + build;
  std::printf("%-8s %8zu | %7.1f %7.1f %7.1f %7.1f %7.1f %7.1f | %7.1f | %6zu %5d %6.1f %6.1f\n", kind.c_str(), n,
              per_particle_ns(morton, n), per_particle_ns(hilbert, n), per_particle_ns(sort, n),
              per_particle_ns(permute, n), per_particle_ns(build, n), per_particle_ns(build_quadrupole, n),
              per_particle_ns(total, n), tree.nodes().size(), tree.depth(), bytes, bytes_quadrupole);
}

struct sorted_data {
  particle_set<3> set;
  nt::hashed_tree<3> tree;
};

sorted_data prepare(const std::string& kind, std::size_t n, double neighbours) {
  sorted_data data{make_set(kind, n, neighbours), {}};
  ntree_test::sort_by_key(data.set, nt::curve::hilbert);
  data.tree.build(data.set.keys.data(), data.set.x.data(), data.set.m.data(), data.set.h.data(), n, {16, false});
  return data;
}

// A density-like sum over neighbours, the work a physics loop does per pair (kept cheap).
struct density_sum {
  const particle_set<3>* set;
  double* rho;
  void operator()(std::size_t a, std::size_t b) const {
    const double r2 = nt::distance_squared<3>(set->x[a], set->x[b]);
    const double q = 1 - r2 / (4 * set->h[a] * set->h[a]);
    rho[a] += set->m[b] * q * q * q;
  }
};

void search_rows(const std::string& kind, std::size_t n, double neighbours, int repeats) {
  sorted_data data = prepare(kind, n, neighbours);
  const auto& set = data.set;
  const auto space = nt::domain<3>::open();
  const nt::search_options options{nt::interaction::gather, 2.0, nullptr};
  std::vector<double> rho(n);
  const density_sum sum{&set, rho.data()};

  nt::neighbour_lists lists;
  nt::group_walk<3> reference_walk(options, {32, 0});
  reference_walk.find_neighbours(data.tree, space, lists);
  const double mean_neighbours = static_cast<double>(lists.total()) / static_cast<double>(n);

  std::printf("\n%s, N = %zu, gather 2h, mean neighbours %.1f\n", kind.c_str(), n, mean_neighbours);
  std::printf("%-40s %12s %10s %12s %10s\n", "method (callback: density-like sum)", "ns/particle", "vs group",
              "list/group", "group size");

  double group_seconds = 0;
  const nt::group_options groupings[] = {{8, 0, 0, 2048},  {16, 0, 0, 2048},   {32, 0, 0, 2048},
                                         {64, 0, 0, 2048}, {32, 0, 0.5, 2048}, {32, 0, 0, std::size_t(-1)}};
  for (const nt::group_options& grouping : groupings) {
    nt::group_walk<3> walk(options, grouping);
    const double seconds = best_time(repeats, [&] {
      std::fill(rho.begin(), rho.end(), 0.0);
      walk.for_each_neighbour(data.tree, space, sum);
    });
    const bool reference =
      grouping.max_group_size == 32 && grouping.max_group_extent == 0 && grouping.max_list_length == 2048;
    if (reference) group_seconds = seconds;
    const double groups = static_cast<double>(walk.groups().size());
    char name[64];
    std::snprintf(name, sizeof name, "group walk, <= %zu, extent %.1f%s", grouping.max_group_size,
                  grouping.max_group_extent, grouping.max_list_length == std::size_t(-1) ? ", no fallback" : "");
    std::printf("%-40s %12.1f %10s %12.1f %10.1f\n", name, per_particle_ns(seconds, n), "",
                static_cast<double>(walk.interaction_list_entries()) / groups, static_cast<double>(n) / groups);
  }
  const auto row = [&](const char* name, double seconds) {
    std::printf("%-40s %12.1f %10.2f\n", name, per_particle_ns(seconds, n), seconds / group_seconds);
  };
  row("group walk, groups <= 32 (reference)", group_seconds);
  row("group walk, groups <= 32, CSR lists",
      best_time(repeats, [&] { reference_walk.find_neighbours(data.tree, space, lists); }));
  std::vector<double> rho_from_lists(n);
  row("density from CSR lists (reuse cost)", best_time(repeats, [&] {
        flecsi_lite::forall(
          n,
          [&](std::size_t a) {
            double total = 0;
            for (std::size_t j = lists.offsets[a]; j < lists.offsets[a + 1]; ++j) {
              const std::size_t b = lists.neighbours[j];
              const double r2 = nt::distance_squared<3>(set.x[a], set.x[b]);
              const double q = 1 - r2 / (4 * set.h[a] * set.h[a]);
              total += set.m[b] * q * q * q;
            }
            rho_from_lists[a] = total;
          },
          "bench::csr_density");
      }));
  nt::radius_search<3> per_target(options);
  row("per-target tree walk, callback", best_time(repeats, [&] {
        std::fill(rho.begin(), rho.end(), 0.0);
        per_target.for_each_neighbour(data.tree, space, sum);
      }));
  row("per-target tree walk, CSR lists",
      best_time(repeats, [&] { per_target.find_neighbours(data.tree, space, lists); }));
  const double h_max = *std::max_element(set.h.begin(), set.h.end());
  nt::cell_list<3> cells;
  const double cell_build =
    best_time(repeats, [&] { cells.build(set.x.data(), set.h.data(), n, options.support * h_max); });
  const double cell_search = best_time(repeats, [&] {
    std::fill(rho.begin(), rho.end(), 0.0);
    flecsi_lite::forall(
      n, [&](std::size_t a) { cells.for_each_neighbour(a, options, sum); }, "bench::cell_list",
      flecsi_lite::dynamic_schedule{});
  });
  row("uniform cell list (build, serial)", cell_build);
  row("uniform cell list, callback", cell_search);
}

void brute_force_row(std::size_t n, int repeats) {
  sorted_data data = prepare("uniform", n, 80);
  const auto space = nt::domain<3>::open();
  const nt::search_options options{nt::interaction::gather, 2.0, nullptr};
  nt::neighbour_lists lists;
  nt::group_walk<3> walk(options, {32, 0});
  const double tree_seconds = best_time(repeats, [&] { walk.find_neighbours(data.tree, space, lists); });
  const double brute_seconds = best_time(
    1, [&] { nt::brute_force_neighbours<3>(data.set.x.data(), data.set.h.data(), n, space, options, lists); });
  std::printf(
    "\nuniform, N = %zu: brute force %.1f us/particle, group walk %.3f us/particle, "
    "brute force / group walk = %.0f\n",
    n, 1e6 * brute_seconds / static_cast<double>(n), 1e6 * tree_seconds / static_cast<double>(n),
    brute_seconds / tree_seconds);
}

}  // namespace

int main(int argc, char** argv) {
  Kokkos::ScopeGuard kokkos(argc, argv);
  // Arguments: --quick (smaller sizes), and any of build, search, brute (default: all).
  bool quick = false;
  bool sections[3] = {false, false, false};
  const char* names[3] = {"build", "search", "brute"};
  for (int i = 1; i < argc; ++i) {
    if (std::strcmp(argv[i], "--quick") == 0) quick = true;
    for (int k = 0; k < 3; ++k)
      if (std::strcmp(argv[i], names[k]) == 0) sections[k] = true;
  }
  if (!sections[0] && !sections[1] && !sections[2]) sections[0] = sections[1] = sections[2] = true;
  const int repeats = quick ? 1 : 3;
  std::printf("ntree benchmark, 3D, %d host threads (%s)\n", flecsi_lite::concurrency(),
              typeid(flecsi_lite::execution_space).name());

  if (sections[0]) {
    std::printf(
      "\nBuild: ns per particle (keys in a box, radix sort of (key, id), permutation of "
      "5 fields, tree with bucket 16)\n");
    std::printf("%-8s %8s | %7s %7s %7s %7s %7s %7s | %7s | %6s %5s %6s %6s\n", "set", "N", "morton", "hilbert", "sort",
                "permute", "tree", "tree+Q", "total", "nodes", "depth", "B/part", "B+Q");
    const std::size_t large = quick ? std::size_t{200000} : std::size_t{1000000};
    for (const std::size_t n : {std::size_t{100000}, large})
      for (const char* kind : {"uniform", "plummer"}) build_row(kind, n, repeats);
    std::printf(
      "(total = hilbert + sort + permute + tree; B/part = tree bytes per particle, "
      "B+Q with quadrupoles)\n");
  }
  const std::size_t search_n = quick ? 20000 : 100000;
  if (sections[1]) {
    search_rows("uniform", search_n, 80, repeats);
    search_rows("plummer", search_n, 60, repeats);
  }
  if (sections[2]) brute_force_row(quick ? 5000 : 20000, repeats);
  return 0;
}
