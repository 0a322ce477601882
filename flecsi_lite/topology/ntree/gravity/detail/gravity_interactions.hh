// The gravity walk's inner steps (Barnes 1990's group walk): the interaction list of one target
// group by a depth-first descent, and the sum over it for the group's targets in a fixed order
// (nodes in visit order, then particles in visit order); the pair term is shared with the
// direct-summation reference.
#pragma once

#include "flecsi_lite/topology/ntree/gravity/detail/gravity_opening.hh"
#include "flecsi_lite/topology/ntree/space.hh"
#include "flecsi_lite/topology/ntree/tree/hashed_tree.hh"
#include "flecsi_lite/topology/ntree/tree/multipole.hh"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

namespace flecsi_lite::topology::ntree::detail {

/// One group's interaction list: the accepted nodes (indices, and copies of their moments) and
/// the particles of the opened leaves (copies), each in visit order: the per-target loop
/// streams through contiguous arrays. One per thread; the vectors only grow, so a warm list
/// allocates nothing.
template<int D>
struct gravity_list {
  std::vector<std::uint32_t> nodes;
  std::vector<double> node_mass;
  std::vector<point<D>> node_centre;
  std::vector<quadrupole<D>> node_quadrupole;
  std::vector<point<D>> x;
  std::vector<double> m;
  std::vector<double> h;
  std::vector<std::uint32_t> stack;

  void clear() {
    nodes.clear();
    node_mass.clear();
    node_centre.clear();
    node_quadrupole.clear();
    x.clear();
    m.clear();
    h.clear();
  }
  std::size_t particles() const { return x.size(); }
};

/// Fills `list` for `group`: depth-first from the root, children in node order; an accepted
/// node is kept (with its quadrupole from `quadrupoles`, zero when nullptr), an opened leaf
/// gives its particles, an opened inner node its children. Sources is gravity_sources<D>,
/// Group target_group<D>, Options gravity_options.
template<int D, class Sources, class Group, class Options>
void build_gravity_list(const Sources& sources, const Group& group, const Options& options,
                        const quadrupole<D>* quadrupoles, gravity_list<D>& list) {
  list.clear();
  if (sources.node_count == 0) return;
  std::vector<std::uint32_t>& stack = list.stack;
  stack.assign(1, 0);
  while (!stack.empty()) {
    const std::uint32_t index = stack.back();
    stack.pop_back();
    const tree_node<D>& node = sources.nodes[index];
    if (node.size() == 0) continue;
    if (gravity_accepts<D>(node, group, options)) {
      list.nodes.push_back(index);
      list.node_mass.push_back(node.mass);
      list.node_centre.push_back(node.centre);
      list.node_quadrupole.push_back(quadrupoles ? quadrupoles[index] : quadrupole<D>::Zero());
    } else if (node.is_leaf()) {
      for (std::uint32_t b = node.begin; b < node.end; ++b) {
        list.x.push_back(sources.x[b]);
        list.m.push_back(sources.m[b]);
        list.h.push_back(sources.h ? sources.h[b] : 0.0);
      }
    } else {
      // Pushed last child first, so that they are popped in node order.
      for (std::uint32_t c = node.first_child + node.child_count; c-- > node.first_child;) stack.push_back(c);
    }
  }
}

/// Adds source (x_j, m_j, h_j) to the running sums of target (x_i, h_i) through `near`: the one
/// pair term of both the walk and the direct sum (same operations, so theta = 0 gives the
/// direct sum bit for bit when both visit the sources in the same order).
template<int D, class Near>
inline void add_pair(const point<D>& xi, double hi, const point<D>& xj, double mj, double hj, const Near& near,
                     point<D>& acceleration, double& potential) {
  point<D> d;
  double r2 = 0;
  for (int k = 0; k < D; ++k) {
    d[k] = xi[k] - xj[k];
    r2 += d[k] * d[k];
  }
  const auto pair = near(std::sqrt(r2), hi, hj);
  potential += mj * pair.potential;
  const double factor = mj * pair.radial;
  for (int k = 0; k < D; ++k) acceleration[k] -= factor * d[k];
}

/// Targets of one group in structure-of-arrays blocks: the loop over a block's targets for one
/// source has independent lanes, so the compiler vectorises it (omp simd) while every target
/// still adds its terms in the list's order, bit for bit as one target alone would.
template<int D>
struct target_block {
  static constexpr std::size_t width = 32;
  std::size_t count = 0;
  alignas(64) double x[D][width];
  alignas(64) double h[width];
  alignas(64) double a[D][width];
  alignas(64) double phi[width];
  // One source's pair terms per target (the particle pass).
  alignas(64) double r[width];
  alignas(64) double potential[width];
  alignas(64) double radial[width];
};

/// Distances beyond newtonian_margin * near_factor * max(h_i, h_j) take the Newtonian pair
/// {-1/r, 1/r^3} without calling `near`, which must give exactly that there (the walk's
/// contract); the margin keeps rounding in near's own test (r / h against its support) away.
inline constexpr double newtonian_margin = 1 + 1e-9;

/// The field of `list` at the block's targets: first the accepted nodes in visit order (the
/// multipole_field arithmetic of multipole.hh), then the particles in visit order, added to
/// running sums from zero. near_factor is gravity_options::near_factor.
template<int D, class Near>
inline void sum_gravity_list(const gravity_list<D>& list, double near_factor, const Near& near, target_block<D>& b) {
  const std::size_t count = b.count;
  for (std::size_t t = 0; t < count; ++t) {
    for (int k = 0; k < D; ++k) b.a[k][t] = 0;
    b.phi[t] = 0;
  }
  for (std::size_t n = 0; n < list.nodes.size(); ++n) {
    const double m = list.node_mass[n];
    const point<D>& c = list.node_centre[n];
    double q[D][D];
    for (int i = 0; i < D; ++i)
      for (int j = 0; j < D; ++j) q[i][j] = list.node_quadrupole[n](i, j);
#pragma omp simd
    for (std::size_t t = 0; t < count; ++t) {
      double r[D], qr[D];
      for (int k = 0; k < D; ++k) r[k] = b.x[k][t] - c[k];
      double r2 = 0, rqr = 0;
      for (int i = 0; i < D; ++i) {
        qr[i] = 0;
        for (int j = 0; j < D; ++j) qr[i] += q[i][j] * r[j];
        r2 += r[i] * r[i];
      }
      for (int i = 0; i < D; ++i) rqr += r[i] * qr[i];
      const double inverse_r = 1 / std::sqrt(r2);
      const double inverse_r2 = inverse_r * inverse_r;
      const double inverse_r3 = inverse_r2 * inverse_r;
      const double inverse_r5 = inverse_r3 * inverse_r2;
      const double along_r = -m * inverse_r3 - 2.5 * rqr * inverse_r5 * inverse_r2;
      for (int k = 0; k < D; ++k) b.a[k][t] += along_r * r[k] + inverse_r5 * qr[k];
      b.phi[t] += -m * inverse_r - 0.5 * rqr * inverse_r2 * inverse_r2 * inverse_r;
    }
  }
  const double newtonian_factor = newtonian_margin * near_factor;
  for (std::size_t p = 0; p < list.particles(); ++p) {
    const point<D>& xp = list.x[p];
    const double mp = list.m[p], hp = list.h[p];
#pragma omp simd
    for (std::size_t t = 0; t < count; ++t) {
      double r2 = 0;
      for (int k = 0; k < D; ++k) {
        const double d = b.x[k][t] - xp[k];
        r2 += d * d;
      }
      const double r = std::sqrt(r2);
      b.r[t] = r;
      b.potential[t] = -1 / r;
      b.radial[t] = 1 / (r * r * r);
    }
    for (std::size_t t = 0; t < count; ++t)
      if (!(b.r[t] > newtonian_factor * std::max(b.h[t], hp))) {
        const auto pair = near(b.r[t], b.h[t], hp);
        b.potential[t] = pair.potential;
        b.radial[t] = pair.radial;
      }
#pragma omp simd
    for (std::size_t t = 0; t < count; ++t) {
      b.phi[t] += mp * b.potential[t];
      const double factor = mp * b.radial[t];
      for (int k = 0; k < D; ++k) b.a[k][t] -= factor * (b.x[k][t] - xp[k]);
    }
  }
}

/// The field of `list` at one target (x, h): a block of one.
template<int D, class Near>
inline void sum_gravity_list(const gravity_list<D>& list, const point<D>& x, double h, double near_factor,
                             const Near& near, point<D>& acceleration, double& potential) {
  target_block<D> block;
  block.count = 1;
  for (int k = 0; k < D; ++k) block.x[k][0] = x[k];
  block.h[0] = h;
  sum_gravity_list<D>(list, near_factor, near, block);
  for (int k = 0; k < D; ++k) acceleration[k] = block.a[k][0];
  potential = block.phi[0];
}

}  // namespace flecsi_lite::topology::ntree::detail
