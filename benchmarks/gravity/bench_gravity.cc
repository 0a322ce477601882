// Benchmark of the gravity walk (gravity.hh): time per particle of the walk at theta 0.5 and 0.7
// (and GADGET-2's relative criterion) against direct summation, with the interactions per
// particle and the force errors, on Evrard spheres of 1e4 to 1e5 particles, from one run.
#include "flecsi_lite/topology/ntree/gravity/direct_gravity.hh"
#include "flecsi_lite/topology/ntree/gravity/gravity.hh"
#include "tests/flecsi_lite/topology/ntree/gravity_sets.hh"

#include <Kokkos_Core.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstring>
#include <ctime>
#include <functional>
#include <string>
#include <vector>

namespace nt = flecsi_lite::topology::ntree;
using ntree_test::particle_set;

namespace {

// Best of `repeats` runs of `work`: wall-clock and process CPU seconds (with one thread the CPU
// time is what a loaded machine distorts least).
struct timing {
  double wall = 1e300, cpu = 1e300;
};
timing best_time(int repeats, const std::function<void()>& work) {
  timing best;
  for (int r = 0; r < repeats; ++r) {
    const std::clock_t cpu_start = std::clock();
    const auto start = std::chrono::steady_clock::now();
    work();
    const auto stop = std::chrono::steady_clock::now();
    const std::clock_t cpu_stop = std::clock();
    best.wall = std::min(best.wall, std::chrono::duration<double>(stop - start).count());
    best.cpu = std::min(best.cpu, static_cast<double>(cpu_stop - cpu_start) / CLOCKS_PER_SEC);
  }
  return best;
}

double ns_per(double seconds, std::size_t n) { return 1e9 * seconds / static_cast<double>(n); }

// Relative force errors of `a` (all particles) at the sampled targets `which` against `exact`.
ntree_test::percentiles errors(const std::vector<nt::point<3>>& a, const std::vector<nt::point<3>>& exact,
                               const std::vector<std::size_t>& which) {
  std::vector<double> e(which.size());
  for (std::size_t t = 0; t < which.size(); ++t) {
    const auto reference = nt::as_column_vector<3>(exact[t]);
    e[t] = (nt::as_column_vector<3>(a[which[t]]) - reference).norm() / reference.norm();
  }
  return ntree_test::percentiles_of(e);
}

void row(std::size_t n, int repeats) {
  particle_set<3> set = ntree_test::evrard_sphere(n, 3);
  ntree_test::sort_by_key(set, nt::curve::hilbert);
  nt::hashed_tree<3> tree;
  const timing build = best_time(repeats, [&] {
    tree.build(set.keys.data(), set.x.data(), set.m.data(), set.h.data(), n, {16, true});
  });
  const auto groups = nt::target_groups<3>(tree, 32);
  const auto sources = nt::gravity_sources_of(tree);
  const ntree_test::spline_pair near;

  // Direct summation on a sample of targets (its cost per target is the same for all).
  std::vector<std::size_t> which;
  const std::size_t stride = std::max<std::size_t>(1, n / 2000);
  for (std::size_t i = 0; i < n; i += stride) which.push_back(i);
  std::vector<nt::point<3>> exact(which.size());
  const timing direct = best_time(1, [&] {
    nt::direct_gravity<3>(set.x.data(), set.m.data(), set.h.data(), n, which.data(), which.size(), near, exact.data(),
                          nullptr);
  });
  const double direct_ns = ns_per(direct.wall, which.size());
  const double direct_cpu_ns = ns_per(direct.cpu, which.size());

  std::vector<nt::point<3>> a(n);
  std::vector<double> phi(n);
  std::vector<double> magnitude(n);
  const auto run = [&](const char* label, const nt::gravity_options& options,
                       const std::vector<nt::target_group<3>>& walked) {
    nt::gravity_counts counts;
    const timing seconds = best_time(repeats, [&] {
      counts = nt::gravity_walk<3>(sources, walked, {set.x.data(), set.h.data()}, options, near, a.data(), phi.data());
    });
    const auto e = errors(a, exact, which);
    std::printf("%7zu %-13s | %8.0f %8.0f %6.0f | %7.1f %7.1f | %8.2e %8.2e | %6.1f %6.1f\n", n, label,
                ns_per(seconds.wall, n), ns_per(seconds.cpu, n), ns_per(build.cpu, n),
                static_cast<double>(counts.node_interactions) / static_cast<double>(n),
                static_cast<double>(counts.particle_interactions) / static_cast<double>(n), e.median, e.p99,
                direct_ns / ns_per(seconds.wall, n), direct_cpu_ns / ns_per(seconds.cpu, n));
  };
  nt::gravity_options options;
  options.theta = 0.5;
  run("theta 0.5", options, groups);
  options.theta = 0.7;
  run("theta 0.7", options, groups);
  // The relative criterion with the old accelerations from the theta 0.5 walk.
  options.theta = 0.5;
  nt::gravity_walk<3>(sources, groups, {set.x.data(), set.h.data()}, options, near, a.data(), nullptr);
  for (std::size_t i = 0; i < n; ++i) magnitude[i] = nt::as_column_vector<3>(a[i]).norm();
  options.relative_criterion = true;
  run("alpha 0.0025", options, nt::target_groups<3>(tree, 32, magnitude.data()));
  std::printf("%7zu %-13s | %8.0f %8.0f %6s | %7s %7zu |\n", n, "direct", direct_ns, direct_cpu_ns, "", "", n);
}

}  // namespace

int main(int argc, char** argv) {
  Kokkos::ScopeGuard kokkos(argc, argv);
  bool quick = false;
  for (int i = 1; i < argc; ++i)
    if (std::strcmp(argv[i], "--quick") == 0) quick = true;
  const int repeats = quick ? 1 : 3;
  std::printf(
    "gravity benchmark: Evrard sphere (rho ~ 1/r), cubic-spline softening with the SPH "
    "h (40 neighbours), bucket 16, groups of 32; %d host threads\n",
    flecsi_lite::concurrency());
  std::printf("%7s %-13s | %8s %8s %6s | %7s %7s | %8s %8s | %6s %6s\n", "N", "walk", "wall ns", "cpu ns", "tree",
              "nodes", "parts", "err med", "err p99", "x wall", "x cpu");
  for (const std::size_t n : {std::size_t{10000}, std::size_t{30000}, std::size_t{100000}}) {
    if (quick && n > 30000) break;
    row(n, repeats);
  }
  std::printf(
    "(wall / cpu ns: walk time per target; tree: cpu ns per particle of the build with "
    "quadrupoles; nodes, parts: interactions per target; err: |a - a_direct| / "
    "|a_direct| on ~2000 sampled targets; x wall / x cpu: direct time per target over "
    "the walk's)\n");
}
