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

/// One group's interaction list: the accepted nodes (indices) and the particles of the opened
/// leaves (copied, so the per-target loop streams through them), each in visit order. One per
/// thread; the vectors only grow, so a warm list allocates nothing.
template<int D>
struct gravity_list {
  std::vector<std::uint32_t> nodes;
  std::vector<point<D>> x;
  std::vector<double> m;
  std::vector<double> h;
  std::vector<std::uint32_t> stack;

  void clear() {
    nodes.clear();
    x.clear();
    m.clear();
    h.clear();
  }
  std::size_t particles() const { return x.size(); }
};

/// Fills `list` for `group`: depth-first from the root, children in node order; an accepted
/// node is kept, an opened leaf gives its particles, an opened inner node its children.
/// Sources is gravity_sources<D>, Group target_group<D>, Options gravity_options.
template<int D, class Sources, class Group, class Options>
void build_gravity_list(const Sources& sources, const Group& group, const Options& options,
                        gravity_list<D>& list) {
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
/// multipoles; `quadrupoles` nullptr: monopoles), then the particles in visit order.
template<int D, class Sources, class Near>
inline void sum_gravity_list(const Sources& sources, const gravity_list<D>& list,
                             const quadrupole<D>* quadrupoles, const point<D>& x, double h,
                             const Near& near, point<D>& acceleration, double& potential) {
  point<D> a{};
  double phi = 0;
  const quadrupole<D> none = quadrupole<D>::Zero();
  for (const std::uint32_t index : list.nodes) {
    const tree_node<D>& node = sources.nodes[index];
    const quadrupole<D>& q = quadrupoles ? quadrupoles[index] : none;
    phi += multipole_potential<D>(node.mass, node.center, q, x);
    const point<D> field = multipole_acceleration<D>(node.mass, node.center, q, x);
    for (int k = 0; k < D; ++k) a[k] += field[k];
  }
  for (std::size_t p = 0; p < list.particles(); ++p)
    add_pair<D>(x, h, list.x[p], list.m[p], list.h[p], near, a, phi);
  acceleration = a;
  potential = phi;
}

} // namespace flecsi_lite::topology::ntree::detail
