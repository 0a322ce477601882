// The gravity walk's inner steps (Barnes 1990's group walk): the interaction list of one target
// group by a depth-first descent, and the sum over it for one target in a fixed order (nodes in
// visit order, then particles in visit order), shared with the direct-summation reference.
#pragma once

#include "flecsi_lite/topology/ntree/detail/gravity_opening.hh"
#include "flecsi_lite/topology/ntree/hashed_tree.hh"
#include "flecsi_lite/topology/ntree/multipole.hh"
#include "flecsi_lite/topology/ntree/space.hh"

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
  std::vector<point<D>> node_center;
  std::vector<quadrupole<D>> node_quadrupole;
  std::vector<point<D>> x;
  std::vector<double> m;
  std::vector<double> h;
  std::vector<std::uint32_t> stack;

  void clear() {
    nodes.clear();
    node_mass.clear();
    node_center.clear();
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
      list.node_center.push_back(node.center);
      list.node_quadrupole.push_back(quadrupoles ? quadrupoles[index] : quadrupole<D>::Zero());
    } else if (node.is_leaf()) {
      for (std::uint32_t b = node.begin; b < node.end; ++b) {
        list.x.push_back(sources.x[b]);
        list.m.push_back(sources.m[b]);
        list.h.push_back(sources.h ? sources.h[b] : 0.0);
      }
    } else {
      // Pushed last child first, so that they are popped in node order.
      for (std::uint32_t c = node.first_child + node.child_count; c-- > node.first_child;)
        stack.push_back(c);
    }
  }
}

/// Adds source (x_j, m_j, h_j) to the running sums of target (x_i, h_i) through `near`: the one
/// pair term of both the walk and the direct sum (same operations, so theta = 0 gives the
/// direct sum bit for bit when both visit the sources in the same order).
template<int D, class Near>
inline void add_pair(const point<D>& xi, double hi, const point<D>& xj, double mj, double hj,
                     const Near& near, point<D>& acceleration, double& potential) {
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

/// The field at target (x, h) of `list`: first the accepted nodes in visit order (their
/// multipoles), then the particles in visit order, added to running sums from zero.
template<int D, class Near>
inline void sum_gravity_list(const gravity_list<D>& list, const point<D>& x, double h,
                             const Near& near, point<D>& acceleration, double& potential) {
  point<D> a{};
  double phi = 0;
  for (std::size_t n = 0; n < list.nodes.size(); ++n) {
    point<D> field;
    phi += multipole_field<D>(list.node_mass[n], list.node_center[n], list.node_quadrupole[n], x,
                              field);
    for (int k = 0; k < D; ++k) a[k] += field[k];
  }
  for (std::size_t p = 0; p < list.particles(); ++p)
    add_pair<D>(x, h, list.x[p], list.m[p], list.h[p], near, a, phi);
  acceleration = a;
  potential = phi;
}

} // namespace flecsi_lite::topology::ntree::detail
