// The neighbour lists the SPH tasks sum over (compressed sparse rows over the owned particles,
// neighbours as storage indices, owned or ghost, in the canonical (key, id) order, each with
// its periodic image shift); filled by the ntree search (seed Algorithm 2), so that the physics
// does not depend on the tree. The targets are split into INTERIOR (every neighbour owned) and
// BOUNDARY (some neighbour a ghost), so that the interior sums can run while the ghosts travel;
// and the check that no two particles coincide.
#pragma once

#include "specialization/numerics/simd.hh"
#include "specialization/sph/model/fields.hh"
#include "specialization/sph/model/tasks.hh"

#include "flecsi_lite/execution.hh"
#include "flecsi_lite/topology/ntree.hh"
#include "flecsi_lite/util.hh"

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace flecsph::sph {

namespace tree = flecsi_lite::topology::ntree;

/// Vocabulary: particle a is a TARGET (owned here); each of its NEIGHBOURS b is seen as the image
/// x_b + shift, so that the separation is r_ab = x_a - (x_b + shift). The lists hold, for every
/// owned a, at least every b with |r_ab| < reach * max(h_a, h_b) for the current positions and h
/// values, in ascending (key, id, shift) order of the last distribution: sums over them do not
/// depend on the rank count. They are searched with list_reach = reach (1 + list_skin) at the
/// positions listed_x and h listed_h and kept over the steps while that still holds
/// (list_reuse.hh; Verlet 1967). The pair tasks skip the entries beyond the kernel support, so a
/// sum takes the same pairs in the same order as over the lists of a search now.
/// Each entry packs b with its shift code, and each row is kept as runs of consecutive
/// neighbours (ntree::shift_storage::runs, the `neighbour_lists` key's default): about 1.2 bytes
/// per entry instead of 4. The pair loops read a target's row decoded (neighbour_walk::row),
/// entry for entry the packed row.
template<int D>
struct neighbourhood {
  tree::neighbour_lists lists;  ///< offsets per owned particle, rows of packed entries (b, shift code), as runs or not
  std::array<vector<D>, tree::shift_code_count<D>> shift_table{};  ///< displacement per shift code
  double reach = 2.0;               ///< the reach the lists hold, in units of h (>= the kernel support 2)
  double list_reach = 2.0;          ///< the reach they were searched with (>= reach)
  std::vector<vector<D>> listed_x;  ///< position of each owned particle at the search (with a skin)
  std::vector<double> listed_h;     ///< its h then (with a skin)
  /// The owned targets whose lists hold owned particles only (a periodic image of an owned
  /// particle is owned data), and the others, whose lists hold a ghost; each ascending, together
  /// every target of the search once (every owned particle, or the active ones of
  /// search_active_neighbours). Filled with the lists (split_targets).
  std::vector<std::uint32_t> interior, boundary;
  /// With individual time steps, the active targets of each set (time_bins.hh, select_active):
  /// the pair tasks then sum for those only. A search selects every target again.
  std::vector<std::uint32_t> active_interior, active_boundary;
  /// The tick whose step ends select_active chose the active targets for; -1: none chosen.
  std::int64_t active_tick = -1;

  std::size_t size() const { return lists.size(); }
  bool active_selected() const { return active_tick >= 0; }
  /// The targets of a pair task's launch, chosen by its ghost privilege: without ghost access
  /// (na) the interior ones, with it the boundary ones (the active ones among them when selected).
  const std::vector<std::uint32_t>& targets(flecsi_lite::privilege ghost) const {
    if (active_selected()) return ghost == flecsi_lite::na ? active_interior : active_boundary;
    return ghost == flecsi_lite::na ? interior : boundary;
  }
  /// Mean number of list entries per target (itself included).
  double mean_count() const { return size() ? double(lists.total()) / double(size()) : 0.0; }
  /// Memory held (allocated room included): the lists, the positions and h of the search and
  /// the target sets.
  std::size_t bytes() const {
    return lists.offsets.capacity() * sizeof(std::size_t) + lists.neighbours.capacity() * sizeof(std::uint32_t) +
           lists.shifts.capacity() * sizeof(tree::shift_code) + lists.runs.capacity() +
           listed_x.capacity() * sizeof(vector<D>) + listed_h.capacity() * sizeof(double) +
           (interior.capacity() + boundary.capacity() + active_interior.capacity() + active_boundary.capacity()) *
             sizeof(std::uint32_t);
  }
};

/// The neighbourhood as tasks share it: the executor orders the search that writes it before the
/// pair tasks that read it, and those before the next search (no hand-placed wait).
template<int D>
using tracked_neighbourhood = flecsi_lite::tracked<neighbourhood<D>>;
/// The parameter of a task that reads the lists.
template<int D>
using neighbours_ro = flecsi_lite::tracked_accessor<neighbourhood<D>, flecsi_lite::ro>;

/// Total length of this rank's neighbour lists: the mean neighbour count, and the work of the pair
/// tasks here (reduced over the ranks for the balance reports).
template<int D>
double neighbour_total(neighbours_ro<D> neighbours) {
  return static_cast<double>(neighbours->lists.total());
}

/// One target's list as the inner loops read it: entries j = 0 .. size(), each a packed
/// (b, shift code), with separations that include the periodic images.
template<int D>
struct neighbour_row {
  const std::uint32_t* entries;
  std::size_t count;
  const vector<D>* shift_table;

  std::size_t size() const { return count; }
  std::size_t neighbour(std::size_t j) const { return tree::packed_neighbour(entries[j]); }
  /// The periodic image shift of entry j (zero for the particle itself).
  const vector<D>& shift(std::size_t j) const { return shift_table[tree::packed_shift(entries[j])]; }
  /// Whether entry j is a periodic image (its shift is not the zero vector).
  bool shifted(std::size_t j) const { return tree::packed_shift(entries[j]) != tree::zero_shift<D>; }

  /// separation() for the entries j0 .. j0 + Lanes at once (past the end, lanes repeat the last
  /// entry; the caller masks them): their neighbours in b, r_ab as packs per axis, and |r_ab|^2,
  /// each lane bitwise separation(). The shifts are loaded only when an entry is an image (most
  /// are not): the table's zero shift is +0, and x - (+0) = x.
  template<class T, std::size_t Lanes>
  FLECSPH_SIMD_INLINE T separations(std::size_t j0, const vector<D>& x_a, const vector<D>* x, std::size_t (&b)[Lanes],
                                    T (&r)[D]) const {
    std::size_t j[Lanes];
    bool any_shifted = false;
    for (std::size_t i = 0; i < Lanes; ++i) {
      j[i] = std::min(j0 + i, count - 1);
      b[i] = neighbour(j[i]);
      any_shifted |= shifted(j[i]);
    }
    for (int k = 0; k < D; ++k) r[k] = x_a[k] - physics::simd::generate<T>([&](std::size_t i) { return x[b[i]][k]; });
    if (any_shifted)
      for (int k = 0; k < D; ++k) r[k] -= physics::simd::generate<T>([&](std::size_t i) { return shift(j[i])[k]; });
    T r2 = 0.0;
    for (int k = 0; k < D; ++k) r2 += r[k] * r[k];
    return r2;
  }

  /// r_ab = (x_a - x_b) - shift_j for entry j, and |r_ab|^2. Grouped so that the pair (b, a),
  /// seen under the opposite shift, gives exactly the negated vector and the same squared
  /// distance: pair terms are then antisymmetric to the last bit.
  double separation(const vector<D>& x_a, const vector<D>& x_b, std::size_t j, vector<D>& r) const {
    const vector<D>& s = shift(j);
    double r2 = 0;
    for (int k = 0; k < D; ++k) {
      r[k] = (x_a[k] - x_b[k]) - s[k];
      r2 += r[k] * r[k];
    }
    return r2;
  }
};

/// A view of a neighbourhood for the inner loops: the row of each target, decoded from its runs
/// (or read in place from plain packed lists, as tests and benchmarks build them).
template<int D>
struct neighbour_walk {
  const tree::neighbour_lists* lists;
  const vector<D>* shift_table;

  explicit neighbour_walk(const neighbourhood<D>& n) : lists(&n.lists), shift_table(n.shift_table.data()) {}

  /// Target a's row. Runs are decoded into a buffer of the calling thread, which the thread's
  /// next row() reuses: a thread reads one row at a time (as every pair loop does).
  neighbour_row<D> row(std::size_t a) const {
    const std::size_t begin = lists->offsets[a], end = lists->offsets[a + 1];
    if (!lists->in_runs) return {lists->neighbours.data() + begin, end - begin, shift_table};
    if (begin == end) return {nullptr, 0, shift_table};  // not a target
    static thread_local std::vector<std::uint32_t> decoded;
    const std::uint8_t* coded = lists->runs.data() + begin;
    const std::size_t count = tree::runs::row_count(coded);
    if (decoded.size() < count + tree::runs::decode_padding)
      decoded.resize(count + count / 4 + tree::runs::decode_padding);
    tree::runs::decode_row(coded, decoded.data());
    return {decoded.data(), count, shift_table};
  }
};

/// The loop of the pair tasks over the targets: dynamically scheduled, `chunk` targets at a time,
/// because the work per particle varies (Newton iterations of h, viscous pairs near shocks) and
/// an even split of the particles leaves a thread waiting. Each particle's own sums are
/// unchanged by the schedule.
inline constexpr flecsi_lite::dynamic_schedule target_schedule{256};

/// Gives back the room of `v` beyond a quarter more than its size: the lists of the first search
/// (from the initial guess of h) would otherwise hold memory for good.
template<class T>
void release_spare_room(std::vector<T>& v) {
  if (v.capacity() > v.size() + v.size() / 4) v.shrink_to_fit();
}

/// Splits the targets of `n` (the owned particles a with chosen[a] != 0; all without `chosen`)
/// into interior and boundary: a target is interior when every entry of its list is an owned
/// particle (storage index below the owned count). `particles` counts the owned and ghost
/// particles the lists may name: without ghosts (one rank) every target is interior, and the
/// lists are not scanned. A search of the active particles (individual time steps) splits those
/// only: the other rows are empty, and a pass over all of them cost as much as the split.
template<int D>
void split_targets(neighbourhood<D>& n, std::size_t particles, const std::uint8_t* chosen = nullptr) {
  const std::size_t owned = n.size();
  n.interior.clear();
  n.boundary.clear();
  n.active_tick = -1;
  std::vector<std::uint32_t>& targets = n.interior;  // every target first, ascending
  for (std::size_t a = 0; a < owned; ++a)
    if (chosen == nullptr || chosen[a] != 0) targets.push_back(static_cast<std::uint32_t>(a));
  if (particles <= owned) return;
  std::vector<std::uint8_t> needs_ghosts(targets.size());
  const neighbour_walk<D> walk(n);
  flecsi_lite::forall(
    targets.size(),
    [&](std::size_t i) {
      const neighbour_row<D> row = walk.row(targets[i]);
      bool ghost = false;
      for (std::size_t j = 0; j < row.size() && !ghost; ++j) ghost = row.neighbour(j) >= owned;
      needs_ghosts[i] = ghost;
    },
    "sph::split_targets");
  std::size_t kept = 0;
  for (std::size_t i = 0; i < targets.size(); ++i)
    if (needs_ghosts[i])
      n.boundary.push_back(targets[i]);
    else
      targets[kept++] = targets[i];
  targets.resize(kept);
}

/// The groups of the searches' walk (seed Algorithm 2): 64 targets share one interaction list.
/// With 93 neighbours (Sedov 3D, 50^3, 1 x 1) the search took 0.110 s per step with groups of 64,
/// 0.126 s with 32 and 0.112 s with 128 (portable build), and 0.089-0.095 s with 64 or 128
/// against 0.108-0.113 s with 32 (AVX-512): fewer tree walks for a slightly longer filter. The
/// searches of the active particles only (individual time steps) use them too since the walk
/// skips the groups without a target and bounds a group's reach by its targets alone (stop 49:
/// Sedov 3D 100^3, eta 1.42, to t = 0.02, AVX-512: 17.0 -> 13.2 s of search with 64 instead of
/// 32; 50^3 1.48 -> 1.09 s, flat from 48 to 96, 2.3 s with 256; 40^3 to t = 0.01 unchanged).
inline constexpr tree::group_options search_groups{64};

namespace detail {
/// What every search task does after the tree's search: the shift table, the reaches, the
/// positions and h searched with, the interior and boundary targets.
template<int D>
void finish_search(const tree::local_tree<D>& local, neighbourhood<D>& out, double support, double list_reach,
                   const tree::domain<D>& space, const std::uint8_t* chosen = nullptr) {
  release_spare_room(out.lists.neighbours);
  release_spare_room(out.lists.runs);
  const auto table = space.shift_table();
  for (std::size_t c = 0; c < table.size(); ++c)
    for (int k = 0; k < D; ++k) out.shift_table[c][k] = table[c][k];
  out.reach = support;
  out.list_reach = list_reach;
  const std::size_t owned = local.owned_size();
  split_targets(out, local.size(), chosen);
  if (!(list_reach > support)) {
    // Without a skin a list never outlives a step (list_reuse.hh: any motion, and h not
    // shrinking, uses up a skin of 0): no positions and h to keep, 32 bytes a particle in 3D.
    out.listed_x = {};
    out.listed_h = {};
    return;
  }
  out.listed_x.resize(owned);
  out.listed_h.resize(owned);
  const std::size_t* sorted = local.storage_to_sorted().data();
  const auto* x = local.positions().data();
  const double* h = local.smoothing_lengths().data();
  flecsi_lite::forall(
    owned,
    [&](std::size_t a) {
      out.listed_x[a] = x[sorted[a]];
      out.listed_h[a] = h[sorted[a]];
    },
    "sph::search_neighbours::listed");
}
}  // namespace detail

/// The search task: fills `out` from the local tree's search over owned targets (symmetric
/// criterion, reach `support` (1 + list_skin)), with the positions and h it searched with (the
/// tree's sorted copies, current after a build or refit), its rows kept as `storage` (runs or
/// packed). The tree keeps its search workspaces, hence rw.
template<int D>
void search_neighbours(typename flecsi_lite::tracked<tree::local_tree<D>>::template accessor<flecsi_lite::rw> local,
                       typename tracked_neighbourhood<D>::template accessor<flecsi_lite::wo> out, double support,
                       double list_skin, tree::domain<D> space, tree::shift_storage storage) {
  const double list_reach = support * (1 + list_skin);
  local->find_neighbours(tree::interaction::symmetric, list_reach, space, out->lists, search_groups, storage);
  detail::finish_search(*local, *out, support, list_reach, space);
}

/// The same for the owned particles whose step ends at tick `next` only (individual time steps,
/// time_bins.hh): the other rows are empty, and the search costs what the active targets need.
template<int D>
void search_active_neighbours(
  typename flecsi_lite::tracked<tree::local_tree<D>>::template accessor<flecsi_lite::rw> local,
  typename tracked_neighbourhood<D>::template accessor<flecsi_lite::wo> out, double support, tree::domain<D> space,
  tree::shift_storage storage, std::int64_t next, ro<std::int64_t> step_end) {
  std::vector<std::uint8_t> active(step_end.size());
  std::size_t targets = 0;
  flecsi_lite::forall_reduce(
    active.size(),
    [&](std::size_t a, std::size_t& count) {
      active[a] = step_end(a) == next;
      count += active[a];
    },
    Kokkos::Sum<std::size_t>(targets), "sph::search_active_neighbours::mask");
  // The rows of a few targets (at most a sixteenth of the particles) stay packed, 4 bytes an
  // entry: coding them as runs and decoding them in every pair loop cost 5% of an individual-step
  // run, for at most 25 bytes a particle, far below the all-active steps' runs (122). The
  // entries, hence every sum, are the same (docs/performance.md).
  const bool few = 16 * targets < active.size();
  const auto rows = storage == tree::shift_storage::runs && few ? tree::shift_storage::packed : storage;
  local->find_neighbours_of(active, tree::interaction::symmetric, support, space, out->lists, search_groups, rows);
  detail::finish_search(*local, *out, support, support, space, active.data());
}

/// Launches the search of `out` on the tree of `p` (after ntree::distribute() or
/// refresh_local_tree(), which the executor orders before it), `list_skin` beyond the reach.
template<int D>
void find_neighbours(particle_tree<D>& p, tracked_neighbourhood<D>& out, double list_skin,
                     tree::shift_storage storage = tree::shift_storage::runs) {
  flecsi_lite::execute<search_neighbours<D>>(p.local_tree_object(), out, p.settings().support, list_skin, p.space(),
                                             storage);
}

/// Two distinct particles at the same position, the pair with the smallest ids (first < second);
/// `found()` is false when there is none. SPH cannot have them: their h, and their pair forces
/// along r_ab / |r_ab|, are undefined.
struct coincident_pair {
  std::uint64_t first = ~std::uint64_t(0), second = ~std::uint64_t(0);
  double x[3] = {0, 0, 0};  ///< the position (first D components)
  bool found() const { return first != ~std::uint64_t(0); }
};

/// Over ranks: the pair with the smallest (first, second), the same on every rank count.
struct coincident_reduction {
  static coincident_pair combine(const coincident_pair& a, const coincident_pair& b) {
    return (b.first < a.first || (b.first == a.first && b.second < a.second)) ? b : a;
  }
};

/// The task: a neighbour at distance 0 that is not the target itself (every such pair is in the
/// lists of its owned members, so the reduction over ranks finds the same pair on any rank count).
template<int D>
coincident_pair find_coincident(neighbours_ro<D> neighbours_object, ro_with_ghosts<vector<D>> x,
                                ro_with_ghosts<std::uint64_t> id) {
  const neighbourhood<D>& neighbours = *neighbours_object;
  const neighbour_walk<D> walk(neighbours);
  coincident_pair best;
  vector<D> r;
  for (std::size_t a = 0; a < neighbours.size(); ++a) {
    const neighbour_row<D> row = walk.row(a);
    for (std::size_t j = 0; j < row.size(); ++j) {
      const std::size_t b = row.neighbour(j);
      if (b == a || row.separation(x(a), x(b), j, r) != 0) continue;
      coincident_pair pair;
      pair.first = std::min(id(a), id(b));
      pair.second = std::max(id(a), id(b));
      for (int k = 0; k < D; ++k) pair.x[k] = x(a)[k];
      best = coincident_reduction::combine(best, pair);
    }
  }
  return best;
}

}  // namespace flecsph::sph
