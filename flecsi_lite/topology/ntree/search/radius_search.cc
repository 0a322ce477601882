// radius_search<D> compiled once per dimension (radius_search.hh declares it extern): its list
// building is the same code in every program, so it is generated here, not in each translation
// unit. (for_each_neighbour takes the caller's functor and stays in the header.)
#include "flecsi_lite/topology/ntree/search/radius_search.hh"

namespace flecsi_lite::topology::ntree {

template<int D>
void radius_search<D>::find_neighbours(const hashed_tree<D>& tree, const domain<D>& space, neighbour_lists& out) {
  check_periodic_reach(tree, space, options_.support);
  const std::size_t n = tree.size();
  const std::size_t chunks = chunk_count_for(n);
  const auto entries = neighbour_list_builder::entries_for({}, space.any_periodic(), n);
  const auto shifts = space.shift_table();
  const std::uint32_t allowed = space.allowed_shifts();
  const search_options options = options_;
  do {  // twice when a chunk outgrew its region (neighbour_list_builder)
    builder_.start(n, chunks, out, entries);
    dispatch_search(options.kind, space.any_periodic(), [&](auto kind, auto periodic) {
      flecsi_lite::forall(
        chunks,
        [&](std::size_t c) {
          auto& part = builder_[c];
          const std::size_t first = n * c / chunks;
          const std::size_t last = n * (c + 1) / chunks;
          for (std::size_t a = first; a < last; ++a) {
            if (!options.is_target(a)) continue;
            walk_target<D, decltype(kind)::value, decltype(periodic)::value>(
              tree, shifts, allowed, tree.positions()[a], tree.smoothing_lengths()[a], options.support,
              [&](std::size_t b, shift_code code) { part.append(a, static_cast<std::uint32_t>(b), code, entries); });
          }
        },
        "ntree::radius_search::lists", flecsi_lite::dynamic_schedule{});
    });
  } while (!builder_.finish(out, entries));
}

template class radius_search<1>;
template class radius_search<2>;
template class radius_search<3>;
}  // namespace flecsi_lite::topology::ntree
