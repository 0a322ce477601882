// Branch sharing of the distributed ntree (FleCSPH, seed sec. 2.3.3 and Fig. 2.3): each rank
// describes its particles by a few top branches of its tree, all ranks exchange them
// (MPI_Allgatherv), and an owned particle is SHARED with rank r when a particle of one of r's
// branches may interact with it (under some periodic image); owned particles shared with nobody
// are EXCLUSIVE, and the copies a rank receives are its GHOSTS.
#pragma once

#include "flecsi_lite/execution/forall.hh"
#include "flecsi_lite/runtime/context.hh"
#include "flecsi_lite/topology/ntree/detail/search_dispatch.hh"
#include "flecsi_lite/topology/ntree/periodic.hh"
#include "flecsi_lite/topology/ntree/tree/hashed_tree.hh"

#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <queue>
#include <vector>

namespace flecsi_lite::topology::ntree {

/// A top branch: `bounds`, the tight box of a node's particles, and three outer bounds of the
/// union of their balls of radius r_p = support * factor * h_p: the bounding box `reach`, the
/// sphere (`centre`, `radius`) and the box `bounds` widened by support * factor * h_max.
///
/// Why these suffice: particles a (of the branch) and i interact when
/// |x_a - x_i| < support * max(h_a, h_i). If h_i is the larger, i is closer than support * h_i
/// to the branch's box; otherwise i lies in a's ball, inside all three outer bounds (each alone
/// would do; together they are much tighter where balls differ in size, as in the outskirts of
/// a cluster). The same holds in floating point: box distances never exceed point distances, and
/// the relative padding of the reach box and the sphere covers the rounding of x ± r and |x - c|.
template<int D>
struct branch {
  box<D> bounds = box<D>::empty();
  box<D> reach = box<D>::empty();
  point<D> centre{};
  double radius = 0;
  double h_max = 0;
};

namespace detail {
/// The reach box of one particle, padded outwards so that every point whose computed distance to
/// x is below r along each axis lies inside.
template<int D>
box<D> ball_box(const point<D>& x, double r) {
  box<D> b;
  for (int k = 0; k < D; ++k) {
    const double pad = 1e-14 * (std::abs(x[k]) + r);
    b.lo[k] = (x[k] - r) - pad;
    b.hi[k] = (x[k] + r) + pad;
  }
  return b;
}

template<int D>
double volume(const box<D>& b) {
  double v = 1;
  for (int k = 0; k < D; ++k) v *= std::max(0.0, b.hi[k] - b.lo[k]);
  return v;
}
}  // namespace detail

/// At most `count` nodes of `tree` that together hold all its particles, as branches. From the
/// root down, the node with the highest priority is replaced by its children while the total
/// stays within `count`; the priority is the node's particle count times h_max / h_min, so that
/// branches are finer where particles are, and where smoothing lengths differ (a few far
/// particles of large h must not lend their reach to a whole branch of small-h particles).
template<int D>
std::vector<branch<D>> top_branches(const hashed_tree<D>& tree, std::size_t count, double support, double factor) {
  std::vector<branch<D>> result;
  const std::size_t nodes = tree.nodes().size();
  if (tree.size() == 0 || count == 0) return result;
  // Bottom-up: reach box and smallest h of every node (children come after their parents).
  std::vector<box<D>> reach(nodes, box<D>::empty());
  std::vector<double> h_min(nodes, 0);
  const point<D>* x = tree.positions();
  const double* h = tree.smoothing_lengths();
  const double scale = support * factor;
  for (std::size_t index = nodes; index-- > 0;) {
    const tree_node<D>& node = tree.node(static_cast<std::uint32_t>(index));
    double smallest = node.h_max;
    if (node.is_leaf()) {
      for (std::uint32_t i = node.begin; i < node.end; ++i) {
        reach[index].extend(detail::ball_box<D>(x[i], scale * h[i]));
        smallest = std::min(smallest, h[i]);
      }
    } else {
      for (std::uint32_t c = node.first_child; c < node.first_child + node.child_count; ++c) {
        reach[index].extend(reach[c]);
        smallest = std::min(smallest, h_min[c]);
      }
    }
    h_min[index] = smallest;
  }
  const auto priority = [&](std::uint32_t index) {
    const tree_node<D>& node = tree.node(index);
    const double spread = h_min[index] > 0 ? node.h_max / h_min[index] : (node.h_max > 0 ? 1e6 : 1.0);
    return static_cast<double>(node.size()) * spread;
  };
  const auto lower = [&](std::uint32_t a, std::uint32_t b) {
    const double pa = priority(a), pb = priority(b);
    return pa < pb || (pa == pb && a > b);
  };
  std::priority_queue<std::uint32_t, std::vector<std::uint32_t>, decltype(lower)> open(lower);
  std::vector<std::uint32_t> done;
  open.push(0);
  while (!open.empty()) {
    const std::uint32_t index = open.top();
    const tree_node<D>& node = tree.node(index);
    if (node.is_leaf() || done.size() + open.size() - 1 + node.child_count > count) break;
    open.pop();
    for (std::uint32_t c = node.first_child; c < node.first_child + node.child_count; ++c) {
      if (tree.node(c).is_leaf())
        done.push_back(c);
      else
        open.push(c);
    }
  }
  for (; !open.empty(); open.pop()) done.push_back(open.top());
  std::sort(done.begin(), done.end());
  for (const std::uint32_t index : done) {
    const tree_node<D>& node = tree.node(index);
    branch<D> b;
    b.bounds = node.bounds;
    b.reach = reach[index];
    b.h_max = node.h_max;
    b.centre = node.bounds.centre();
    for (std::uint32_t i = node.begin; i < node.end; ++i)
      b.radius = std::max(b.radius, std::sqrt(distance_squared<D>(x[i], b.centre)) + scale * h[i]);
    b.radius *= 1 + 1e-12;
    result.push_back(b);
  }
  return result;
}

/// Collective: every rank's branches, indexed by rank (MPI_Allgatherv).
template<int D>
std::vector<std::vector<branch<D>>> share_branches(const std::vector<branch<D>>& mine, MPI_Comm comm) {
  int size = 1;
  MPI_Comm_size(comm, &size);
  const int my_count = static_cast<int>(mine.size());
  std::vector<int> counts(size), bytes(size), offsets(size);
  runtime::check_mpi(MPI_Allgather(&my_count, 1, MPI_INT, counts.data(), 1, MPI_INT, comm),
                     "ntree branch sharing: counts");
  std::size_t total = 0;
  for (int r = 0; r < size; ++r) {
    bytes[r] = counts[r] * static_cast<int>(sizeof(branch<D>));
    offsets[r] = static_cast<int>(total * sizeof(branch<D>));
    total += static_cast<std::size_t>(counts[r]);
  }
  std::vector<branch<D>> all(total);
  runtime::check_mpi(MPI_Allgatherv(mine.data(), my_count * static_cast<int>(sizeof(branch<D>)), MPI_BYTE, all.data(),
                                    bytes.data(), offsets.data(), MPI_BYTE, comm),
                     "ntree branch sharing: branches");
  std::vector<std::vector<branch<D>>> result(size);
  for (int r = 0, first = 0; r < size; first += counts[r], ++r)
    result[r].assign(all.begin() + first, all.begin() + first + counts[r]);
  return result;
}

/// Calls visit(i) once for every particle i of `tree` (sorted index) that a particle of branch
/// `b` may interact with under some allowed image shift: its image x_i + shift is closer than
/// support * factor * h_i to b.bounds, or lies within all outer bounds of b's balls. Nodes are
/// pruned with the same tests on their boxes (with their h_max), which never reject a box
/// holding such a particle.
template<int D, class Visit>
void for_each_within_branch(const hashed_tree<D>& tree, const domain<D>& space, const branch<D>& b, double support,
                            double factor, Visit&& visit) {
  if (tree.size() == 0) return;
  const auto shifts = space.shift_table();
  const point<D>* x = tree.positions();
  const double* h = tree.smoothing_lengths();
  const double scale = support * factor;
  const double branch_reach = scale * b.h_max;
  // Inside every outer bound of the union of b's balls (x a point or the box of a node).
  const auto in_balls = [&](const auto& where) {
    return distance_squared<D>(b.bounds, where) < branch_reach * branch_reach &&
           distance_squared<D>(where, b.centre) < b.radius * b.radius;
  };
  walk_entry stack[walk_stack_size<D>];
  int top = 0;
  stack[top++] = walk_entry{0, space.allowed_shifts()};
  while (top > 0) {
    const walk_entry entry = stack[--top];
    const tree_node<D>& node = tree.node(entry.node);
    const double reach = scale * node.h_max;
    std::uint32_t pass = 0;
    for (std::uint32_t rest = entry.shifts; rest != 0; rest &= rest - 1) {
      const int code = __builtin_ctz(rest);
      const box<D> image = node.bounds.shifted(shifts[code]);
      if (distance_squared<D>(b.bounds, image) < reach * reach || (b.reach.intersects(image) && in_balls(image)))
        pass |= std::uint32_t{1} << code;
    }
    if (pass == 0) continue;
    if (!node.is_leaf()) {
      for (std::uint32_t c = node.first_child + node.child_count; c-- > node.first_child;)
        stack[top++] = walk_entry{c, pass};
      continue;
    }
    for (std::uint32_t i = node.begin; i < node.end; ++i) {
      const double particle_reach = scale * h[i];
      for (std::uint32_t rest = pass; rest != 0; rest &= rest - 1) {
        const int code = __builtin_ctz(rest);
        point<D> image;  // the same rounding as the searches' images
        for (int k = 0; k < D; ++k) image[k] = x[i][k] + shifts[code][k];
        if (within_radius(distance_squared<D>(b.bounds, image), particle_reach) ||
            (b.reach.contains(image) && in_balls(image))) {
          visit(static_cast<std::size_t>(i));
          break;
        }
      }
    }
  }
}

/// For every rank r other than `me`: the particles of `tree` (sorted indices, ascending) that a
/// particle of one of branches[r] may interact with, i.e. those to send to r as its ghosts.
/// Every source that a symmetric (or gather) search of r's owned targets with radius
/// support * max(h_a, h_b) can find is among them, periodic images included.
template<int D>
std::vector<std::vector<std::size_t>> shared_particles(const hashed_tree<D>& tree, const domain<D>& space,
                                                       const std::vector<std::vector<branch<D>>>& branches, int me,
                                                       double support, double factor) {
  const std::size_t ranks = branches.size();
  // One work item per (rank, branch), walked in parallel, each collecting its own hits.
  std::vector<std::pair<std::size_t, std::size_t>> items;
  for (std::size_t r = 0; r < ranks; ++r)
    if (static_cast<int>(r) != me)
      for (std::size_t j = 0; j < branches[r].size(); ++j) items.emplace_back(r, j);
  std::vector<std::vector<std::uint32_t>> hits(items.size());
  flecsi_lite::forall(
    items.size(),
    [&](std::size_t w) {
      const auto [r, j] = items[w];
      for_each_within_branch<D>(tree, space, branches[r][j], support, factor,
                                [&hits, w](std::size_t i) { hits[w].push_back(static_cast<std::uint32_t>(i)); });
    },
    "ntree::shared_particles", flecsi_lite::dynamic_schedule{});

  std::vector<std::vector<std::size_t>> result(ranks);
  std::vector<std::uint8_t> marked(tree.size(), 0);
  for (std::size_t w = 0; w < items.size();) {
    const std::size_t r = items[w].first;
    std::vector<std::size_t>& list = result[r];
    for (; w < items.size() && items[w].first == r; ++w)
      for (const std::uint32_t i : hits[w])
        if (!marked[i]) {
          marked[i] = 1;
          list.push_back(i);
        }
    std::sort(list.begin(), list.end());
    for (const std::size_t i : list) marked[i] = 0;
  }
  return result;
}

}  // namespace flecsi_lite::topology::ntree
