// Plumbing shared by the ntree neighbour searches: compile-time dispatch on the interaction kind
// and on periodicity, the check that periodic images are unique, and the user-functor adaptor.
#pragma once

#include "flecsi_lite/topology/ntree/periodic.hh"
#include "flecsi_lite/topology/ntree/search/neighbour_lists.hh"
#include "flecsi_lite/topology/ntree/tree/hashed_tree.hh"

#include <cassert>
#include <cstdint>
#include <stdexcept>
#include <type_traits>

namespace flecsi_lite::topology::ntree {

/// The image shifts among `candidates` under which `node` may hold a neighbour of `target` (a
/// point, or a group's box), whose own reach is `target_radius`. Box distances never exceed a
/// member's distance, so pruning with them is exact.
template<interaction Kind, bool Periodic, class Node, class Target, class Shifts>
std::uint32_t reachable_shifts(const Node& node, const Target& target, double target_radius, double support,
                               const Shifts& shifts, std::uint32_t candidates) {
  const double reach = interaction_radius<Kind>(1.0, target_radius, support * node.h_max);
  const double reach_squared = reach * reach;
  if constexpr (Periodic) {
    std::uint32_t pass = 0;
    for (std::uint32_t rest = candidates; rest != 0; rest &= rest - 1) {
      const int code = __builtin_ctz(rest);
      if (node.template distance_squared_to<true>(target, shifts[code]) < reach_squared)
        pass |= std::uint32_t{1} << code;
    }
    return pass;
  } else {
    return node.template distance_squared_to<false>(target, shifts[0]) < reach_squared ? candidates : 0u;
  }
}

/// Calls body(kind, periodic) with both as compile-time constants (std::integral_constant), so
/// that the inner loops of a search are compiled once per case without run-time branches.
template<class Body>
void dispatch_search(interaction kind, bool periodic, Body&& body) {
  using gather = std::integral_constant<interaction, interaction::gather>;
  using symmetric = std::integral_constant<interaction, interaction::symmetric>;
  if (kind == interaction::gather) {
    if (periodic)
      body(gather{}, std::true_type{});
    else
      body(gather{}, std::false_type{});
  } else {
    if (periodic)
      body(symmetric{}, std::true_type{});
    else
      body(symmetric{}, std::false_type{});
  }
}

/// Throws unless every interaction radius is at most half of every period: then a source is
/// within reach of a target under at most one image shift, and lists hold each source once.
template<int D>
void check_periodic_reach(const hashed_tree<D>& tree, const domain<D>& space, double support) {
  if (!space.any_periodic() || tree.size() == 0) return;
  for (int k = 0; k < D; ++k)
    if (space.periodic[k] && !(space.period(k) > 0))
      throw std::invalid_argument("ntree: a periodic axis needs a positive period");
  if (2 * support * tree.root().h_max > space.min_period())
    throw std::invalid_argument("ntree: interaction radius exceeds half of a periodic length");
}

/// True when `F` takes the image shift: apply(target, neighbour, shift).
template<int D, class F>
constexpr bool takes_shift = std::is_invocable_v<F&, std::size_t, std::size_t, const point<D>&>;

/// Checks a user functor for apply(target, neighbour) or apply(target, neighbour, shift); the
/// two-argument form cannot place periodic images, so it is refused on a periodic domain.
template<int D, class F>
void check_functor(const domain<D>& space) {
  static_assert(takes_shift<D, F> || std::is_invocable_v<F&, std::size_t, std::size_t>,
                "apply must be callable as apply(target, neighbour) or "
                "apply(target, neighbour, shift)");
  if constexpr (!takes_shift<D, F>) {
    if (space.any_periodic())
      throw std::invalid_argument("ntree: on a periodic domain apply must take the image shift as third argument");
  }
}

/// Calls the user functor with or without the shift vector of `code`.
template<int D, class F>
inline void call_apply(F& apply, std::size_t target, std::size_t neighbour, shift_code code,
                       const std::array<point<D>, shift_code_count<D>>& shifts) {
  if constexpr (takes_shift<D, F>)
    apply(target, neighbour, shifts[code]);
  else
    apply(target, neighbour);
}

/// Room for a depth-first walk: at most (children - 1) nodes wait per level, plus the root.
template<int D>
constexpr int walk_stack_size = max_level<D>*(children_per_cell<D> - 1) + 2;

/// An entry of a walk's stack: a node and the image shifts under which it may still matter.
struct walk_entry {
  std::uint32_t node;
  std::uint32_t shifts;
};

/// The depth-first walk every neighbour search shares: from the root, a node is entered under
/// the image shifts `reachable(node, candidates)` keeps (a mask of shift codes; 0: pruned), and
/// leaf(node, shifts) is called for every leaf reached, in key order (children are pushed last
/// first, so that they are popped in key = index order). Children are pushed unconditionally and
/// kept only if reachable: no branch to mispredict.
template<int D, class Reachable, class Leaf>
void walk_reachable_leaves(const search_node<D>* nodes, std::uint32_t root_candidates, const Reachable& reachable,
                           Leaf&& leaf) {
  walk_entry stack[walk_stack_size<D>];
  int top = 0;
  const std::uint32_t root_pass = reachable(nodes[0], root_candidates);
  if (root_pass != 0) stack[top++] = walk_entry{0, root_pass};
  while (top > 0) {
    const walk_entry entry = stack[--top];
    const search_node<D>& node = nodes[entry.node];
    if (node.is_leaf()) {
      leaf(node, entry.shifts);
      continue;
    }
    for (std::uint32_t c = node.first_child + node.child_count; c-- > node.first_child;) {
      const std::uint32_t pass = reachable(nodes[c], entry.shifts);
      assert(top < walk_stack_size<D>);
      stack[top] = walk_entry{c, pass};
      top += pass != 0;
    }
  }
}

}  // namespace flecsi_lite::topology::ntree
