// group_walk<D> compiled once per dimension (group_walk.hh declares it extern): the neighbour
// search is the same code in every program, so its list building and grouping are defined here and
// generated once, not in each translation unit. (The walks that take a caller's functor stay in the header.)
#include "flecsi_lite/topology/ntree/search/group_walk.hh"

#include <cstring>

namespace flecsi_lite::topology::ntree {

template<int D>
void group_walk<D>::find_neighbours(const hashed_tree<D>& tree, const domain<D>& space, neighbour_lists& out,
                                    const list_layout& layout) {
  const auto kind = neighbour_list_builder::entries_for(layout, space.any_periodic(), tree.size());
  const std::size_t* rename = layout.rename;
  const auto shifts = space.shift_table();
  const auto prepare = [&](std::size_t chunks) {
    builder_.start(rename ? layout.rows : tree.size(), chunks, out, kind);
  };
  do {  // twice when a chunk outgrew its region (neighbour_list_builder)
    run(tree, space, prepare, [&](std::size_t chunk, workspace& work, auto interaction_kind, auto periodic) {
      auto& part = builder_[chunk];
      walk_group<decltype(interaction_kind)::value, decltype(periodic)::value>(
        tree, shifts, space.allowed_shifts(), work,
        [&](std::size_t a, std::size_t count, const auto& neighbour, const auto& shift) {
          part.append(rename ? rename[a] : a, count, neighbour, shift, rename, kind);
        });
    });
  } while (!builder_.finish(out, kind));
}

// Step 1 (FIND_NODES): the groups, by a depth-first descent in key order.
template<int D>
void group_walk<D>::find_groups(const hashed_tree<D>& tree) {
  groups_.clear();
  group_bounds_.assign(1, 0);
  if (tree.size() == 0) return;
  std::vector<std::uint32_t>& stack = group_stack_;
  stack.assign(1, 0);
  while (!stack.empty()) {
    const std::uint32_t index = stack.back();
    stack.pop_back();
    const tree_node<D>& node = tree.node(index);
    const bool small = node.size() <= grouping_.max_group_size ||
                       (grouping_.max_group_mass > 0 && node.mass <= grouping_.max_group_mass);
    const bool compact = grouping_.max_group_extent <= 0 ||
                         node.bounds.max_extent() <= grouping_.max_group_extent * search_.support * node.h_max;
    if (node.is_leaf() || (small && compact)) {
      groups_.push_back(index);
      group_bounds_.push_back(node.end);
      continue;
    }
    for (std::uint32_t c = node.first_child + node.child_count; c-- > node.first_child;) stack.push_back(c);
  }
}

template<int D>
void group_walk<D>::find_groups_with_targets() {
  walked_.clear();
  const std::uint8_t* targets = search_.targets;
  // Whether bytes [begin, end) of the mask hold a nonzero one, eight at a time.
  const auto holds_target = [targets](std::size_t begin, std::size_t end) {
    std::uint64_t any = 0;
    for (; begin + 8 <= end; begin += 8) {
      std::uint64_t word;
      std::memcpy(&word, targets + begin, sizeof(word));
      any |= word;
    }
    for (; begin < end; ++begin) any |= targets[begin];
    return any != 0;
  };
  for (std::size_t g = 0; g < groups_.size(); ++g)
    if (holds_target(group_bounds_[g], group_bounds_[g + 1])) walked_.push_back(static_cast<std::uint32_t>(g));
}

template class group_walk<1>;
template class group_walk<2>;
template class group_walk<3>;
}  // namespace flecsi_lite::topology::ntree
