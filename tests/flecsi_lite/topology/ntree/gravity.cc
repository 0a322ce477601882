// Tests of the gravity walk against direct summation (reference/direct_gravity.hh): target groups
// partition the particles, theta = 0 is the direct sum bit for bit (momentum to round-off),
// force-error percentiles and potential energy at theta 0.5 and 0.7 on uniform, Plummer and
// Evrard spheres, the quadrupoles, the near-field rule and GADGET-2's relative criterion.
#include "flecsi_lite/topology/ntree/gravity/gravity.hh"
#include "flecsi_lite/topology/ntree/gravity/direct_gravity.hh"
#include "tests/flecsi_lite/topology/ntree/gravity_sets.hh"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <memory>
#include <numeric>
#include <string>
#include <vector>

namespace nt = flecsi_lite::topology::ntree;
using namespace ntree_test;

namespace {

using vector3 = nt::column_vector<3>;

// A particle set sorted by key, its tree (with quadrupoles) and its groups.
struct fixture {
  particle_set<3> set;
  nt::hashed_tree<3> tree;
  std::vector<nt::target_group<3>> groups;

  fixture(particle_set<3> particles, std::size_t group_size = 32) : set(std::move(particles)) {
    sort_by_key(set, nt::curve::hilbert);
    tree.build(set.keys.data(), set.x.data(), set.m.data(), set.h.data(), set.size(), {16, true});
    groups = nt::target_groups<3>(tree, group_size);
  }
  std::size_t size() const { return set.size(); }
};

struct field {
  std::vector<nt::point<3>> a;
  std::vector<double> phi;
  nt::gravity_counts counts;
};

template<class Near>
field walk(const fixture& f, const nt::gravity_options& options, const Near& near,
           const std::vector<nt::target_group<3>>* groups = nullptr) {
  field out;
  out.a.resize(f.size());
  out.phi.resize(f.size());
  out.counts = nt::gravity_walk<3>(nt::gravity_sources_of(f.tree), groups ? *groups : f.groups,
                                   {f.set.x.data(), f.set.h.data()}, options, near, out.a.data(), out.phi.data());
  return out;
}

// Direct sums at the targets `which` (all when empty); results indexed like `which`.
template<class Near>
field direct(const fixture& f, const Near& near, const std::vector<std::size_t>& which = {}) {
  field out;
  const std::size_t count = which.empty() ? f.size() : which.size();
  out.a.resize(count);
  out.phi.resize(count);
  nt::direct_gravity<3>(f.set.x.data(), f.set.m.data(), f.set.h.data(), f.size(),
                        which.empty() ? nullptr : which.data(), count, near, out.a.data(), out.phi.data());
  return out;
}

// |a_tree - a_direct| / |a_direct| of the targets `which` (all when empty).
std::vector<double> relative_errors(const field& tree, const field& exact, const std::vector<std::size_t>& which = {}) {
  std::vector<double> errors(exact.a.size());
  for (std::size_t t = 0; t < errors.size(); ++t) {
    const std::size_t i = which.empty() ? t : which[t];
    const vector3 reference = nt::as_column_vector<3>(exact.a[t]);
    errors[t] = (nt::as_column_vector<3>(tree.a[i]) - reference).norm() / reference.norm();
  }
  return errors;
}

// The 1e4-particle sets and their direct sums, computed once for all test cases.
struct reference_set {
  fixture f;
  field exact;
  std::string name;
  explicit reference_set(const std::string& set_name)
      : f(gravity_set(set_name, 10000, 11)), exact(direct(f, spline_pair{})), name(set_name) {}
};
const reference_set& reference(const std::string& name) {
  static std::vector<std::unique_ptr<reference_set>> sets;
  for (const auto& set : sets)
    if (set->name == name) return *set;
  sets.push_back(std::make_unique<reference_set>(name));
  return *sets.back();
}

double potential_energy(const fixture& f, const std::vector<double>& phi) {
  double sum = 0;
  for (std::size_t i = 0; i < f.size(); ++i) sum += 0.5 * f.set.m[i] * phi[i];
  return sum;
}

// Prints and returns the error percentiles of `tree` against `exact`.
percentiles report(const std::string& what, const fixture& f, const field& tree, const field& exact,
                   const std::vector<std::size_t>& which = {}) {
  const percentiles error = percentiles_of(relative_errors(tree, exact, which));
  std::cout << "gravity " << what << " N " << f.size() << ": relative force error median " << error.median
            << ", 99th percentile " << error.p99 << ", max " << error.max << "; per particle "
            << double(tree.counts.node_interactions) / double(f.size()) << " nodes, "
            << double(tree.counts.particle_interactions) / double(f.size()) << " particles\n";
  return error;
}

nt::gravity_options with_theta(double theta) {
  nt::gravity_options options;
  options.theta = theta;
  return options;
}

}  // namespace

TEST_CASE("target groups partition the particles in node order", "[ntree][gravity]") {
  const fixture f(plummer(10000, 5));
  std::vector<double> acceleration_old(f.size());
  for (std::size_t i = 0; i < f.size(); ++i) acceleration_old[i] = 1 + 0.001 * double(i % 997);
  for (const std::size_t group_size : {1, 8, 32, 200}) {
    const auto groups = nt::target_groups<3>(f.tree, group_size, acceleration_old.data());
    REQUIRE(!groups.empty());
    // Node order is level by level; sorted by their first target they tile [0, n).
    auto by_begin = groups;
    std::sort(by_begin.begin(), by_begin.end(), [](const auto& a, const auto& b) { return a.begin < b.begin; });
    std::uint32_t next = 0;
    for (const auto& group : by_begin) {
      REQUIRE(group.begin == next);
      REQUIRE(group.end > group.begin);
      next = group.end;
      double h_max = 0, a_min = 1e300;
      for (std::uint32_t i = group.begin; i < group.end; ++i) {
        REQUIRE(group.bounds.contains(f.set.x[i]));
        h_max = std::max(h_max, f.set.h[i]);
        a_min = std::min(a_min, acceleration_old[i]);
      }
      REQUIRE(group.h_max == h_max);
      REQUIRE(group.acceleration_min == a_min);
    }
    REQUIRE(next == f.size());
    // The groups are, in node order, the nodes that are small (or leaves) with a large parent.
    std::vector<std::size_t> expected;
    const auto& nodes = f.tree.nodes();
    const auto small = [&](const nt::tree_node<3>& node) { return node.size() <= group_size || node.is_leaf(); };
    if (small(nodes[0])) expected.push_back(0);
    for (std::size_t parent = 0; parent < nodes.size() && !small(nodes[0]); ++parent) {
      if (small(nodes[parent])) continue;
      for (std::uint32_t c = nodes[parent].first_child; c < nodes[parent].first_child + nodes[parent].child_count; ++c)
        if (small(nodes[c])) expected.push_back(c);
    }
    std::sort(expected.begin(), expected.end());
    REQUIRE(groups.size() == expected.size());
    for (std::size_t g = 0; g < groups.size(); ++g) {
      const auto& node = nodes[expected[g]];
      REQUIRE(groups[g].begin == node.begin);
      REQUIRE(groups[g].end == node.end);
      REQUIRE(groups[g].bounds == node.bounds);
      REQUIRE(groups[g].h_max == node.h_max);
    }
  }
}

TEST_CASE("theta = 0 is the direct sum bit for bit, and conserves momentum", "[ntree][gravity]") {
  const fixture f(uniform_sphere(3000, 7));
  nt::gravity_options options;
  options.theta = 0;
  const field tree = walk(f, options, spline_pair{});
  const field exact = direct(f, spline_pair{});
  REQUIRE(tree.counts.node_interactions == 0);
  REQUIRE(tree.counts.particle_interactions == f.size() * f.size());
  for (std::size_t i = 0; i < f.size(); ++i) {
    REQUIRE(tree.a[i] == exact.a[i]);
    REQUIRE(tree.phi[i] == exact.phi[i]);
  }
  // Antisymmetric pairs: sum m a vanishes up to the rounding of the sums.
  vector3 momentum = vector3::Zero();
  double scale = 0;
  for (std::size_t i = 0; i < f.size(); ++i) {
    momentum += f.set.m[i] * nt::as_column_vector<3>(tree.a[i]);
    scale += f.set.m[i] * nt::as_column_vector<3>(tree.a[i]).norm();
  }
  INFO("|sum m a| " << momentum.norm() << " against sum m |a| " << scale);
  REQUIRE(momentum.norm() < 1e-13 * scale);
}

TEST_CASE("force errors at theta 0.5 and 0.7 against direct summation", "[ntree][gravity]") {
  for (const std::string name : {"uniform", "plummer", "evrard"}) {
    const reference_set& r = reference(name);
    const double energy = potential_energy(r.f, r.exact.phi);
    for (const double theta : {0.5, 0.7}) {
      const field tree = walk(r.f, with_theta(theta), spline_pair{});
      const percentiles error = report(name + " theta " + std::to_string(theta).substr(0, 3), r.f, tree, r.exact);
      const double energy_error = std::abs(potential_energy(r.f, tree.phi) / energy - 1);
      std::cout << "gravity " << name << " theta " << theta << ": potential energy error " << energy_error << "\n";
      INFO(name << " theta " << theta << ": median " << error.median << ", p99 " << error.p99 << ", energy "
                << energy_error);
      if (theta == 0.5) {
        REQUIRE(error.median <= 6e-4);
        REQUIRE(error.p99 <= 2.5e-3);
      } else {
        REQUIRE(error.p99 <= 1e-2);
      }
      REQUIRE(energy_error <= 1e-3);
    }
  }
}

TEST_CASE("force errors on 1e5 particles, plain Newtonian pairs", "[ntree][gravity]") {
  const fixture f(evrard_sphere(100000, 13));
  std::vector<std::size_t> which;
  for (std::size_t i = 0; i < f.size(); i += 100) which.push_back(i);
  const field exact = direct(f, newtonian_pair{}, which);
  for (const double theta : {0.5, 0.7}) {
    const field tree = walk(f, with_theta(theta), newtonian_pair{});
    const percentiles error =
      report("evrard 1e5 (every 100th target) theta " + std::to_string(theta).substr(0, 3), f, tree, exact, which);
    if (theta == 0.5) {
      REQUIRE(error.median <= 6e-4);
      REQUIRE(error.p99 <= 2.5e-3);
    } else {
      REQUIRE(error.p99 <= 1e-2);
    }
  }
}

TEST_CASE("the quadrupoles count: monopoles alone err clearly more", "[ntree][gravity]") {
  const reference_set& r = reference("evrard");
  nt::gravity_options options;
  const percentiles with = report("evrard quadrupole theta 0.5", r.f, walk(r.f, options, spline_pair{}), r.exact);
  options.quadrupole = false;
  const percentiles without = report("evrard monopole only theta 0.5", r.f, walk(r.f, options, spline_pair{}), r.exact);
  REQUIRE(without.median > 3 * with.median);
  REQUIRE(without.p99 > 3 * with.p99);
}

TEST_CASE("the near-field rule keeps softened pairs out of the multipoles", "[ntree][gravity]") {
  // Softening lengths three times the particle spacing's: many nodes the opening angle would
  // accept lie inside the softening, where a multipole is the wrong (Newtonian) field.
  particle_set<3> set = uniform_sphere(5000, 17);
  for (double& h : set.h) h *= 3;
  const fixture f(std::move(set));
  const field exact = direct(f, spline_pair{});
  nt::gravity_options options = with_theta(0.7);
  const percentiles near = report("uniform h x3 theta 0.7 near_factor 2", f, walk(f, options, spline_pair{}), exact);
  options.near_factor = 0;
  const percentiles none = report("uniform h x3 theta 0.7 near_factor 0", f, walk(f, options, spline_pair{}), exact);
  REQUIRE(near.p99 <= 1e-2);
  REQUIRE(none.p99 > 5 * near.p99);
}

TEST_CASE("GADGET-2's relative criterion reaches comparable accuracy", "[ntree][gravity]") {
  for (const std::string name : {"uniform", "evrard"}) {
    const reference_set& r = reference(name);
    std::vector<double> magnitude(r.f.size());
    for (std::size_t i = 0; i < r.f.size(); ++i) magnitude[i] = nt::as_column_vector<3>(r.exact.a[i]).norm();
    nt::gravity_options options;
    options.relative_criterion = true;
    // Without old accelerations the groups fall back to the geometric test, bit for bit.
    const field geometric = walk(r.f, options, spline_pair{});
    const field fallback = walk(r.f, options, spline_pair{}, &r.f.groups);
    REQUIRE(fallback.a == geometric.a);
    const auto groups = nt::target_groups<3>(r.f.tree, 32, magnitude.data());
    options.theta = 0;  // not used where old accelerations are known
    const field relative = walk(r.f, options, spline_pair{}, &groups);
    const percentiles error = report(name + " relative alpha 0.0025", r.f, relative, r.exact);
    REQUIRE(relative.counts.node_interactions > 0);
    REQUIRE(error.median <= 6e-4);
    REQUIRE(error.p99 <= 2.5e-3);
  }
}

TEST_CASE("interaction lists partition the sources and satisfy the criteria", "[ntree][gravity]") {
  const reference_set& r = reference("plummer");
  const auto sources = nt::gravity_sources_of(r.f.tree);
  const auto& nodes = r.f.tree.nodes();
  nt::detail::gravity_list<3> list;
  for (const double theta : {0.3, 0.7, 1.2}) {
    const nt::gravity_options options = with_theta(theta);
    for (std::size_t g = 0; g < r.f.groups.size(); g += 37) {
      const auto& group = r.f.groups[g];
      nt::detail::build_gravity_list<3>(sources, group, options, sources.quadrupoles, list);
      std::vector<int> seen(r.f.size(), 0);
      for (const std::uint32_t index : list.nodes) {
        const auto& node = nodes[index];
        for (std::uint32_t b = node.begin; b < node.end; ++b) ++seen[b];
        // Outside the softening of every pair, and within the opening angle of every target.
        const double reach = options.near_factor * std::max(node.h_max, group.h_max);
        REQUIRE(nt::distance_squared<3>(node.bounds, group.bounds) > reach * reach);
        for (std::uint32_t i = group.begin; i < group.end; ++i) {
          const double d = std::sqrt(nt::distance_squared<3>(r.f.set.x[i], node.centre));
          REQUIRE(node.bounds.max_extent() < theta * d);
        }
      }
      // The other sources come as particles, in ascending order (leaves in key order).
      std::size_t p = 0;
      for (std::size_t b = 0; b < r.f.size(); ++b) {
        if (seen[b] == 1) continue;
        REQUIRE(seen[b] == 0);
        REQUIRE(p < list.particles());
        REQUIRE(list.x[p] == r.f.set.x[b]);
        REQUIRE(list.m[p] == r.f.set.m[b]);
        ++p;
      }
      REQUIRE(p == list.particles());
    }
  }
}

TEST_CASE("relative criterion: accepted nodes pass eq. 18 and the guard", "[ntree][gravity]") {
  const reference_set& r = reference("evrard");
  std::vector<double> magnitude(r.f.size());
  for (std::size_t i = 0; i < r.f.size(); ++i) magnitude[i] = nt::as_column_vector<3>(r.exact.a[i]).norm();
  const auto groups = nt::target_groups<3>(r.f.tree, 32, magnitude.data());
  const auto sources = nt::gravity_sources_of(r.f.tree);
  nt::gravity_options options;
  options.relative_criterion = true;
  nt::detail::gravity_list<3> list;
  std::size_t accepted = 0;
  for (const double alpha : {0.0005, 0.0025, 0.01}) {
    options.relative_tolerance = alpha;
    for (std::size_t g = 0; g < groups.size(); g += 29) {
      const auto& group = groups[g];
      nt::detail::build_gravity_list<3>(sources, group, options, sources.quadrupoles, list);
      accepted += list.nodes.size();
      std::size_t covered = list.particles();
      for (const std::uint32_t index : list.nodes) {
        const auto& node = r.f.tree.node(index);
        covered += node.size();
        const double side = node.bounds.max_extent();
        const auto centre = node.bounds.centre();
        for (std::uint32_t i = group.begin; i < group.end; ++i) {
          const double r2 = nt::distance_squared<3>(r.f.set.x[i], node.centre);
          REQUIRE(node.mass * side * side <= alpha * magnitude[i] * r2 * r2);
          bool inside = true;  // GADGET-2's guard: |x - centre| < 0.6 side on every axis
          for (int k = 0; k < 3; ++k) inside = inside && std::abs(r.f.set.x[i][k] - centre[k]) < 0.6 * side;
          REQUIRE_FALSE(inside);
        }
      }
      REQUIRE(covered == r.f.size());
    }
  }
  REQUIRE(accepted > 0);
}

TEST_CASE("the walk is its sequential definition, whatever the threads and group order", "[ntree][gravity]") {
  const reference_set& r = reference("plummer");
  const auto sources = nt::gravity_sources_of(r.f.tree);
  const nt::gravity_options options;
  const field parallel = walk(r.f, options, spline_pair{});
  auto reversed = r.f.groups;
  std::reverse(reversed.begin(), reversed.end());
  const field backwards = walk(r.f, options, spline_pair{}, &reversed);
  REQUIRE(backwards.a == parallel.a);
  REQUIRE(backwards.phi == parallel.phi);
  // One thread, group by group: one list per group, then each target over it in order.
  nt::detail::gravity_list<3> list;
  std::uint64_t nodes = 0, particles = 0;
  for (const auto& group : r.f.groups) {
    nt::detail::build_gravity_list<3>(sources, group, options, sources.quadrupoles, list);
    nodes += (group.end - group.begin) * list.nodes.size();
    particles += (group.end - group.begin) * list.particles();
    for (std::uint32_t i = group.begin; i < group.end; ++i) {
      nt::point<3> a;
      double phi;
      nt::detail::sum_gravity_list<3>(list, r.f.set.x[i], r.f.set.h[i], options.near_factor, spline_pair{}, a, phi);
      REQUIRE(a == parallel.a[i]);
      REQUIRE(phi == parallel.phi[i]);
    }
  }
  REQUIRE(parallel.counts.node_interactions == nodes);
  REQUIRE(parallel.counts.particle_interactions == particles);
}

TEST_CASE("wanted targets: only their groups are walked, with the whole walk's bits", "[ntree][gravity]") {
  // Individual time steps ask for the active particles' field (a clustered few) and, later, for
  // the rest: the two partial walks together give every target the whole walk's bits.
  const reference_set& r = reference("plummer");
  const nt::gravity_options options;
  const field whole = walk(r.f, options, spline_pair{});
  std::vector<std::uint8_t> wanted(r.f.size(), 0), rest(r.f.size(), 1);
  for (std::size_t i = 0; i < r.f.size(); i += 97) wanted[i] = 1, rest[i] = 0;  // scattered
  for (std::size_t i = 4000; i < 4300; ++i) wanted[i] = 1, rest[i] = 0;         // a cluster
  const double untouched = -12345;
  field part;
  part.a.assign(r.f.size(), nt::point<3>{untouched, untouched, untouched});
  part.phi.assign(r.f.size(), untouched);
  const auto partial = [&](const std::vector<std::uint8_t>& mask) {
    nt::gravity_targets<3> targets{r.f.set.x.data(), r.f.set.h.data(), mask.data()};
    return nt::gravity_walk<3>(nt::gravity_sources_of(r.f.tree), r.f.groups, targets, options, spline_pair{},
                               part.a.data(), part.phi.data());
  };
  const nt::gravity_counts first = partial(wanted);
  std::size_t walked_groups = 0;
  std::uint64_t walked_targets = 0;
  for (const auto& group : r.f.groups) {
    bool any = false;
    for (std::uint32_t i = group.begin; i < group.end; ++i) any = any || wanted[i];
    walked_groups += any;
    for (std::uint32_t i = group.begin; i < group.end; ++i) {
      if (any) {
        REQUIRE(part.a[i] == whole.a[i]);
        REQUIRE(part.phi[i] == whole.phi[i]);
        ++walked_targets;
      } else {
        REQUIRE(part.phi[i] == untouched);
      }
    }
  }
  REQUIRE(walked_groups > 0);
  REQUIRE(walked_groups < r.f.groups.size());
  REQUIRE(first.node_interactions < whole.counts.node_interactions);
  const nt::gravity_counts second = partial(rest);
  REQUIRE(part.a == whole.a);
  REQUIRE(part.phi == whole.phi);
  // Groups holding both kinds are walked twice; none is skipped by both walks.
  REQUIRE(first.node_interactions + second.node_interactions >= whole.counts.node_interactions);
  std::cout << "gravity wanted targets: " << walked_groups << " of " << r.f.groups.size() << " groups ("
            << walked_targets << " targets) walked for " << std::count(wanted.begin(), wanted.end(), 1)
            << " wanted; node interactions " << first.node_interactions << " of " << whole.counts.node_interactions
            << "\n";
}

TEST_CASE("multipole_field is multipole_potential and multipole_acceleration at once", "[ntree][gravity]") {
  const reference_set& r = reference("evrard");
  const auto& nodes = r.f.tree.nodes();
  for (std::size_t index = 0; index < nodes.size(); index += 13) {
    const auto& node = nodes[index];
    const auto& q = r.f.tree.node_quadrupole(static_cast<std::uint32_t>(index));
    const nt::point<3> x = {node.centre[0] + 0.3, node.centre[1] - 0.7, node.centre[2] + 1.1};
    nt::point<3> a;
    const double phi = nt::multipole_field<3>(node.mass, node.centre, q, x, a);
    REQUIRE(phi == nt::multipole_potential<3>(node.mass, node.centre, q, x));
    REQUIRE(a == nt::multipole_acceleration<3>(node.mass, node.centre, q, x));
  }
}

TEST_CASE("the walk in 2D: theta = 0 is the direct sum, theta 0.5 close to it", "[ntree][gravity]") {
  particle_set<2> set = uniform<2>(3000, 19);
  sort_by_key(set, nt::curve::morton);
  nt::hashed_tree<2> tree;
  tree.build(set.keys.data(), set.x.data(), set.m.data(), set.h.data(), set.size(), {8, true});
  const auto groups = nt::target_groups<2>(tree, 16);
  const std::size_t n = set.size();
  std::vector<nt::point<2>> exact(n), a(n);
  std::vector<double> exact_phi(n), phi(n);
  nt::direct_gravity<2>(set.x.data(), set.m.data(), set.h.data(), n, spline_pair{}, exact.data(), exact_phi.data());
  nt::gravity_options options;
  options.theta = 0;
  nt::gravity_walk<2>(nt::gravity_sources_of(tree), groups, {set.x.data(), set.h.data()}, options, spline_pair{},
                      a.data(), phi.data());
  REQUIRE(a == exact);
  REQUIRE(phi == exact_phi);
  options.theta = 0.5;
  nt::gravity_walk<2>(nt::gravity_sources_of(tree), groups, {set.x.data(), set.h.data()}, options, spline_pair{},
                      a.data(), phi.data());
  std::vector<double> errors(n);
  for (std::size_t i = 0; i < n; ++i)
    errors[i] = (nt::as_column_vector<2>(a[i]) - nt::as_column_vector<2>(exact[i])).norm() /
                nt::as_column_vector<2>(exact[i]).norm();
  const percentiles error = percentiles_of(errors);
  std::cout << "gravity 2D uniform N " << n << " theta 0.5: median " << error.median << ", 99th percentile "
            << error.p99 << "\n";
  REQUIRE(error.median <= 1e-3);
  REQUIRE(error.p99 <= 1e-2);
}
