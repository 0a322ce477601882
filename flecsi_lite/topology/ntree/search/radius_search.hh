// Radius searches with per-particle smoothing lengths on the hashed tree: one depth-first walk
// per target (Barnes & Hut 1986 tree descent with a box-distance test), gather or symmetric,
// periodic images included; neighbours come in ascending sorted index.
#pragma once

#include "flecsi_lite/execution/forall.hh"
#include "flecsi_lite/topology/ntree/detail/search_dispatch.hh"
#include "flecsi_lite/topology/ntree/periodic.hh"
#include "flecsi_lite/topology/ntree/search/detail/neighbour_list_builder.hh"
#include "flecsi_lite/topology/ntree/search/neighbour_lists.hh"
#include "flecsi_lite/topology/ntree/tree/hashed_tree.hh"

#include <cassert>
#include <cstddef>
#include <cstdint>

namespace flecsi_lite::topology::ntree {

/// Calls visit(b, code) for every source image x_b + shift(code) of `tree` within
/// interaction_radius<Kind>(support, h_target, h_b) of `x`, in ascending (b, code). `allowed`
/// is the mask of image shifts to try (domain::allowed_shifts()). Node boxes are pruned with
/// the box distance, which never exceeds a member's distance, so the result is exact.
template<int D, interaction Kind, bool Periodic, class Visit>
void walk_target(const hashed_tree<D>& tree, const std::array<point<D>, shift_code_count<D>>& shifts,
                 std::uint32_t allowed, const point<D>& x, double h_target, double support, Visit&& visit) {
  if (tree.size() == 0) return;
  const search_node<D>* nodes = tree.search_nodes().data();
  const point<D>* positions = tree.positions();
  const double* h = tree.smoothing_lengths();
  const double target_radius = support * h_target;

  const auto reachable = [&](const search_node<D>& node, std::uint32_t candidates) {
    return reachable_shifts<Kind, Periodic>(node, x, target_radius, support, shifts, candidates);
  };

  const auto leaf = [&](const search_node<D>& node, std::uint32_t images) {
    for (std::uint32_t b = node.begin; b < node.end; ++b) {
      const double radius = interaction_radius<Kind>(support, h_target, h[b]);
      if constexpr (Periodic) {
        for (std::uint32_t rest = images; rest != 0; rest &= rest - 1) {
          const int code = __builtin_ctz(rest);
          point<D> image;
          for (int k = 0; k < D; ++k) image[k] = positions[b][k] + shifts[code][k];
          if (within_radius(distance_squared<D>(x, image), radius)) visit(b, static_cast<shift_code>(code));
        }
      } else {
        if (within_radius(distance_squared<D>(x, positions[b]), radius)) visit(b, zero_shift<D>);
      }
    }
  };
  walk_reachable_leaves<D>(nodes, Periodic ? allowed : 1u, reachable, leaf);
}

/// Ball query: calls visit(b, code) for every source image within `radius` of the point `x`
/// (|x - (x_b + shift)| < radius), in ascending (b, code).
template<int D, class Visit>
void for_each_within(const hashed_tree<D>& tree, const domain<D>& space, const point<D>& x, double radius,
                     Visit&& visit) {
  const auto shifts = space.shift_table();
  if (space.any_periodic())
    walk_target<D, interaction::gather, true>(tree, shifts, space.allowed_shifts(), x, radius, 1.0, visit);
  else
    walk_target<D, interaction::gather, false>(tree, shifts, 0, x, radius, 1.0, visit);
}

/// Per-target radius search: each target walks the tree on its own. Simple and exact; the
/// group walk (group_walk.hh) shares one walk among nearby targets and is usually faster.
template<int D>
class radius_search {
 public:
  explicit radius_search(search_options options = {}) : options_(options) {}

  const search_options& options() const { return options_; }

  /// Calls apply(a, b) or apply(a, b, shift) for every target a and each of its neighbours b,
  /// in parallel over targets; the calls for one target come from one thread in ascending b.
  template<class F>
  void for_each_neighbour(const hashed_tree<D>& tree, const domain<D>& space, F&& apply) const {
    check_functor<D, std::remove_reference_t<F>>(space);
    check_periodic_reach(tree, space, options_.support);
    const auto shifts = space.shift_table();
    const std::uint32_t allowed = space.allowed_shifts();
    const search_options options = options_;
    dispatch_search(options.kind, space.any_periodic(), [&](auto kind, auto periodic) {
      flecsi_lite::forall(
        tree.size(),
        [&](std::size_t a) {
          if (!options.is_target(a)) return;
          walk_target<D, decltype(kind)::value, decltype(periodic)::value>(
            tree, shifts, allowed, tree.positions()[a], tree.smoothing_lengths()[a], options.support,
            [&](std::size_t b, shift_code code) { call_apply<D>(apply, a, b, code, shifts); });
        },
        "ntree::radius_search", flecsi_lite::dynamic_schedule{});
    });
  }

  /// Neighbour lists of all targets (shift codes too when the domain is periodic).
  void find_neighbours(const hashed_tree<D>& tree, const domain<D>& space, neighbour_lists& out);

 private:
  search_options options_;
  neighbour_list_builder builder_;
};

// Compiled once per dimension in radius_search.cc, where find_neighbours is defined.
extern template class radius_search<1>;
extern template class radius_search<2>;
extern template class radius_search<3>;

}  // namespace flecsi_lite::topology::ntree
