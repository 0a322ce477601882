// Tests of the gravity walk against direct summation (reference/direct_gravity.hh): target groups
// partition the particles, theta = 0 is the direct sum bit for bit (momentum to round-off),
// force-error percentiles and potential energy at theta 0.5 and 0.7 on uniform, Plummer and
// Evrard spheres, the quadrupoles, the near-field rule and GADGET-2's relative criterion.
#include "flecsi_lite/topology/ntree/gravity.hh"
#include "flecsi_lite/topology/ntree/reference/direct_gravity.hh"
#include "tests/flecsi_lite/topology/ntree/gravity_sets.hh"

#include <catch2/catch.hpp>

#include <algorithm>
#include <cmath>
#include <iostream>
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
                                   {f.set.x.data(), f.set.h.data()}, options, near,
                                   out.a.data(), out.phi.data());
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
                        which.empty() ? nullptr : which.data(), count, near, out.a.data(),
                        out.phi.data());
  return out;
}

// |a_tree - a_direct| / |a_direct| of the targets `which` (all when empty).
std::vector<double> relative_errors(const field& tree, const field& exact,
                                    const std::vector<std::size_t>& which = {}) {
  std::vector<double> errors(exact.a.size());
  for (std::size_t t = 0; t < errors.size(); ++t) {
    const std::size_t i = which.empty() ? t : which[t];
    const vector3 reference = nt::as_column_vector<3>(exact.a[t]);
    errors[t] = (nt::as_column_vector<3>(tree.a[i]) - reference).norm() / reference.norm();
  }
  return errors;
}

double potential_energy(const fixture& f, const std::vector<double>& phi) {
  double sum = 0;
  for (std::size_t i = 0; i < f.size(); ++i) sum += 0.5 * f.set.m[i] * phi[i];
  return sum;
}

} // namespace

TEST_CASE("target groups partition the particles in node order", "[ntree][gravity]") {
  const fixture f(plummer(10000, 5));
  std::vector<double> acceleration_old(f.size());
  for (std::size_t i = 0; i < f.size(); ++i) acceleration_old[i] = 1 + 0.001 * double(i % 997);
  for (const std::size_t group_size : {1, 8, 32, 200}) {
    const auto groups = nt::target_groups<3>(f.tree, group_size, acceleration_old.data());
    REQUIRE(!groups.empty());
    // Node order is level by level; sorted by their first target they tile [0, n).
    auto by_begin = groups;
    std::sort(by_begin.begin(), by_begin.end(),
              [](const auto& a, const auto& b) { return a.begin < b.begin; });
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
    const auto small = [&](const nt::tree_node<3>& node) {
      return node.size() <= group_size || node.is_leaf();
    };
    if (small(nodes[0])) expected.push_back(0);
    for (std::size_t parent = 0; parent < nodes.size() && !small(nodes[0]); ++parent) {
      if (small(nodes[parent])) continue;
      for (std::uint32_t c = nodes[parent].first_child;
           c < nodes[parent].first_child + nodes[parent].child_count; ++c)
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

TEST_CASE("theta = 0 is the direct sum bit for bit, and conserves momentum",
          "[ntree][gravity]") {
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
    const fixture f(gravity_set(name, 10000, 11));
    const field exact = direct(f, spline_pair{});
    const double energy = potential_energy(f, exact.phi);
    for (const double theta : {0.5, 0.7}) {
      nt::gravity_options options;
      options.theta = theta;
      const field tree = walk(f, options, spline_pair{});
      const percentiles error = percentiles_of(relative_errors(tree, exact));
      const double energy_error = std::abs(potential_energy(f, tree.phi) / energy - 1);
      std::cout << "gravity " << name << " N " << f.size() << " theta " << theta
                << ": relative force error median " << error.median << ", 99th percentile "
                << error.p99 << ", max " << error.max << "; potential energy error "
                << energy_error << "; per particle " << double(tree.counts.node_interactions) / double(f.size())
                << " nodes, " << double(tree.counts.particle_interactions) / double(f.size()) << " particles\n";
      INFO(name << " theta " << theta << ": median " << error.median << ", p99 " << error.p99);
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
