// Definitions of the members of ntree<D> (ntree.hh): the distribution pipeline of FleCSPH
// (seed Algorithm 3, lines 5-10): keys, sample sort, all-to-all, local sort, branch sharing,
// ghosts and the local tree.
#pragma once

#include "flecsi_lite/execution/forall.hh"
#include "flecsi_lite/runtime/job_memory.hh"
#include "flecsi_lite/runtime/timers.hh"
#include "flecsi_lite/topology/ntree/distributed/branch_sharing.hh"
#include "flecsi_lite/topology/ntree/distributed/ghost_exchange.hh"
#include "flecsi_lite/topology/ntree/distributed/particle_exchange.hh"
#include "flecsi_lite/topology/ntree/distributed/sample_sort.hh"
#include "flecsi_lite/topology/ntree/distributed/sorted_runs.hh"
#include "flecsi_lite/topology/ntree/sfc/ordering.hh"

#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>

namespace flecsi_lite::topology::ntree {
namespace detail {
/// The task that builds the local tree over owned and ghost particles (owned, then one block per
/// source rank in `runs`): reading the ghosts makes the executor copy them first, so that the
/// topology's ghosts travel by the executor's copies like every other field's, and stay
/// current for the tasks that read them next.
template<int D>
void build_tree(typename tracked<local_tree<D>>::template accessor<wo> local, const std::vector<std::size_t>& runs,
                tree_options options, field<key_type>::accessor<ro, ro> keys,
                field<std::uint64_t>::accessor<ro, ro> ids, typename field<point<D>>::template accessor<ro, ro> x,
                field<double>::accessor<ro, ro> m, field<double>::accessor<ro, ro> h) {
  local->build(keys.data(), ids.data(), x.data(), m.data(), h.data(), x.owned_size(), x.size(), runs, options);
}

/// The task of ntree::refresh_local_tree: reading owned and ghost values makes the executor
/// copy stale ghosts first.
template<int D>
void refit(typename tracked<local_tree<D>>::template accessor<rw> local,
           typename field<point<D>>::template accessor<ro, ro> x, field<double>::accessor<ro, ro> m,
           field<double>::accessor<ro, ro> h) {
  local->refresh(x.data(), m.data(), h.data());
}

/// Seconds since `start` (which moves to now), also added to the named timer.
inline double lap(double& start, const char* timer) {
  const double now = MPI_Wtime(), elapsed = now - start;
  start = now;
  timers::add(timer, elapsed);
  return elapsed;
}
}  // namespace detail

template<int D>
ntree<D>::ntree(const config& settings) : config_(settings) {
  if (config_.balancing == balance::work && !config_.work_weight)
    throw std::invalid_argument("ntree: balancing by work needs a work_weight field");
  if (!(config_.support > 0) || !(config_.ghost_reach_factor >= 1))
    throw std::invalid_argument("ntree: support must be positive and ghost_reach_factor at least 1");
  space_.periodic = config_.periodic;
  space_.bounds = config_.fixed_box ? *config_.fixed_box : domain<D>::open().bounds;
  if (space_.any_periodic()) {
    if (!config_.fixed_box) throw std::invalid_argument("ntree: periodic axes need a fixed_box (the periodic box)");
    for (int k = 0; k < D; ++k)
      if (config_.periodic[k] && !(space_.period(k) > 0))
        throw std::invalid_argument("ntree: a periodic axis needs a box of positive side");
  }
}

template<int D>
ntree<D>::ntree(const config& settings, std::size_t local_count) : ntree(settings) {
  resize(local_count);
}

template<int D>
void ntree<D>::resize(std::size_t local_count) {
  set_plan(data::ghost_plan{});
  set_sizes(local_count, 0);
  values<point<D>>(position);  // the built-in fields exist on every rank
  values<std::uint64_t>(id);
  values<double>(mass);
  values<double>(smoothing_length);
  values<key_type>(key);
  local_.host() = local_tree<D>{};
  branches_.clear();
  exclusive_ = local_count;
  const MPI_Comm comm = runtime::communicator();
  const std::uint64_t mine = local_count;
  MPI_Allreduce(&mine, &global_size_, 1, MPI_UINT64_T, MPI_SUM, comm);
  first_global_index_ = 0;
  MPI_Exscan(&mine, &first_global_index_, 1, MPI_UINT64_T, MPI_SUM, comm);
  if (runtime::rank() == 0) first_global_index_ = 0;  // MPI_Exscan leaves rank 0 undefined
}

template<int D>
box<D> ntree<D>::find_key_box(const point<D>* x, std::size_t n, MPI_Comm comm) const {
  box<D> local = box<D>::empty();
  for (std::size_t i = 0; i < n; ++i) local.extend(x[i]);
  box<D> global;
  MPI_Allreduce(local.lo.data(), global.lo.data(), D, MPI_DOUBLE, MPI_MIN, comm);
  MPI_Allreduce(local.hi.data(), global.hi.data(), D, MPI_DOUBLE, MPI_MAX, comm);
  if (config_.fixed_box) {
    // The same bounding box on every rank, so every rank throws or none does.
    for (int k = 0; k < D; ++k)
      if (config_.periodic[k] && !global.is_empty() &&
          (global.lo[k] < config_.fixed_box->lo[k] || global.hi[k] > config_.fixed_box->hi[k]))
        throw std::invalid_argument("ntree: particles outside the periodic box along axis " + std::to_string(k) +
                                    " (wrap positions into the box before distribute())");
    return *config_.fixed_box;
  }
  if (global.is_empty()) return domain<D>::open().bounds;
  // Padding keeps every axis of positive width (coincident or coplanar particles) at any scale.
  double extent = 0;
  for (int k = 0; k < D; ++k) extent = std::max(extent, global.hi[k] - global.lo[k]);
  for (int k = 0; k < D; ++k) {
    double pad = 1e-6 * std::max({extent, std::abs(global.lo[k]), std::abs(global.hi[k])});
    if (!(pad > 0)) pad = 1e-6;
    global.lo[k] -= pad;
    global.hi[k] += pad;
  }
  return global;
}

template<int D>
void ntree<D>::check_periodic_reach(std::size_t n, MPI_Comm comm) {
  // The searches see each source under one image at most; checked here on every rank together
  // (a search on one rank alone would throw while the others wait in a collective).
  const double* h = values<double>(smoothing_length).view().data();
  double h_max = 0;
  for (std::size_t i = 0; i < n; ++i) h_max = std::max(h_max, h[i]);
  MPI_Allreduce(MPI_IN_PLACE, &h_max, 1, MPI_DOUBLE, MPI_MAX, comm);
  if (2 * config_.support * h_max > space_.min_period())
    throw std::invalid_argument("ntree: interaction radius " + std::to_string(config_.support * h_max) +
                                " exceeds half of a periodic length");
}

template<int D>
distribution_stats ntree<D>::distribute() {
  const MPI_Comm comm = runtime::communicator();
  const int rank = runtime::rank();
  distribution_stats stats;
  wait_all();  // tasks writing the fields finish before they are read here
  double clock = MPI_Wtime();
  const double start = clock;

  // Keys in the global box.
  std::size_t n = owned_size();
  if (space_.any_periodic()) check_periodic_reach(n, comm);
  space_.bounds = find_key_box(values<point<D>>(position).view().data(), n, comm);
  compute_keys<D>(config_.order, space_.bounds, values<point<D>>(position).view().data(), n,
                  values<key_type>(key).view().data());
  stats.time_keys = detail::lap(clock, "ntree::distribute keys");

  // Local (key, id) order, samples, splitters and destination ranges.
  std::vector<std::size_t> order;
  {
    const key_type* keys = values<key_type>(key).view().data();
    const std::uint64_t* ids = values<std::uint64_t>(id).view().data();
    sort_permutation(keys, ids, n, order);
    std::vector<key_id> sorted(n);
    flecsi_lite::forall(
      n,
      [&](std::size_t i) {
        sorted[i] = {keys[order[i]], ids[order[i]]};
      },
      "ntree::distribute::sorted");
    std::vector<double> weights;
    if (config_.balancing == balance::work) {
      const double* w = values<double>(*config_.work_weight).view().data();
      weights.resize(n);
      apply_permutation(order, w, weights.data());
      int invalid =
        std::any_of(weights.begin(), weights.end(), [](double v) { return !(v >= 0) || !std::isfinite(v); });
      MPI_Allreduce(MPI_IN_PLACE, &invalid, 1, MPI_INT, MPI_LOR, comm);
      if (invalid) throw std::invalid_argument("ntree: work weights must be finite and non-negative");
    }
    const auto splitters =
      find_splitters(sorted.data(), weights.empty() ? nullptr : weights.data(), n, config_.sample_bytes, comm);
    const auto bounds = split_sorted(sorted.data(), n, splitters);
    stats.time_splitters = detail::lap(clock, "ntree::distribute splitters");

    // Every particle with every field to its rank; when none changes rank (one rank, or a
    // steady state), the local order is applied instead.
    if (config_.work_weight) values<double>(*config_.work_weight);  // exists on every rank
    const auto fields = storages_to_move(*this, comm);
    for (const auto* f : fields) stats.bytes_per_particle += f->element_size();
    std::uint64_t leaving = n - (bounds[rank + 1] - bounds[rank]), leaving_anywhere = 0;
    MPI_Allreduce(&leaving, &leaving_anywhere, 1, MPI_UINT64_T, MPI_SUM, comm);
    set_plan(data::ghost_plan{});  // the old plan describes the old layout
    if (leaving_anywhere == 0) {
      reorder_owned(order, 0);
      stats.time_exchange = detail::lap(clock, "ntree::distribute exchange");
    } else {
      particle_shipment shipment = exchange_particles(fields, order, bounds, comm);
      set_sizes(shipment.total, 0);
      unpack_particles(fields, shipment);
      stats.sent_away = shipment.sent_away;
      n = shipment.total;
      stats.time_exchange = detail::lap(clock, "ntree::distribute exchange");
      // The block from each source rank is in (key, id) order: merge them.
      const key_type* received_keys = values<key_type>(key).view().data();
      const std::uint64_t* received_ids = values<std::uint64_t>(id).view().data();
      if (!is_sorted(received_keys, received_ids, n)) {
        std::vector<std::size_t> starts;
        for (std::size_t r = 0, at = 0; r < shipment.counts.size(); at += shipment.counts[r++]) starts.push_back(at);
        merge_sorted_runs(received_keys, received_ids, n, std::move(starts), order);
        reorder_owned(order, 0);
      }
    }
  }
  stats.time_local_sort = detail::lap(clock, "ntree::distribute local sort");

  // Branch sharing: who needs which of my particles.
  auto sends = find_ghost_sends(stats.branches);
  {
    std::vector<std::uint8_t> is_shared(n, 0);
    for (const auto& list : sends)
      for (const std::size_t i : list) is_shared[i] = 1;
    stats.shared = static_cast<std::size_t>(std::count(is_shared.begin(), is_shared.end(), std::uint8_t{1}));
    exclusive_ = n - stats.shared;
  }
  stats.time_branches = detail::lap(clock, "ntree::distribute branches");

  // Ghosts: the plan and room for them (every field's ghosts are stale now).
  data::ghost_plan plan = build_sender_plan(std::move(sends), comm);
  set_sizes(n, ghost_count(plan));
  set_plan(std::move(plan));
  stats.time_ghosts = detail::lap(clock, "ntree::distribute ghosts");

  build_local_tree();  // the executor copies the built-in fields' ghosts first
  stats.time_tree = detail::lap(clock, "ntree::distribute local tree");
  // The old layout's arrays are freed (exchange buffers, sorted copies, the fields' old storage).
  runtime::return_free_memory();
  stats.time_total = MPI_Wtime() - start;

  // Statistics over the ranks.
  const std::uint64_t mine = n;
  MPI_Allreduce(&mine, &global_size_, 1, MPI_UINT64_T, MPI_SUM, comm);
  first_global_index_ = 0;
  MPI_Exscan(&mine, &first_global_index_, 1, MPI_UINT64_T, MPI_SUM, comm);
  if (rank == 0) first_global_index_ = 0;
  stats.global_count = global_size_;
  stats.owned = n;
  stats.exclusive = exclusive_;
  stats.ghosts = ghost_size();
  stats.work = static_cast<double>(n);
  if (config_.work_weight) {
    const double* w = values<double>(*config_.work_weight).view().data();
    stats.work = std::accumulate(w, w + n, 0.0);
  }
  unsigned long long counts[3] = {n, stats.sent_away, stats.ghosts}, sums[3];
  unsigned long long smallest = n, largest = n;
  MPI_Allreduce(counts, sums, 3, MPI_UNSIGNED_LONG_LONG, MPI_SUM, comm);
  MPI_Allreduce(MPI_IN_PLACE, &smallest, 1, MPI_UNSIGNED_LONG_LONG, MPI_MIN, comm);
  MPI_Allreduce(MPI_IN_PLACE, &largest, 1, MPI_UNSIGNED_LONG_LONG, MPI_MAX, comm);
  MPI_Allreduce(&stats.work, &stats.work_total, 1, MPI_DOUBLE, MPI_SUM, comm);
  MPI_Allreduce(&stats.work, &stats.work_max, 1, MPI_DOUBLE, MPI_MAX, comm);
  const double ranks = static_cast<double>(runtime::size());
  stats.owned_min = smallest;
  stats.owned_max = largest;
  stats.owned_mean = static_cast<double>(sums[0]) / ranks;
  stats.count_imbalance = sums[0] ? static_cast<double>(largest) / stats.owned_mean : 1.0;
  stats.moved = sums[1];
  stats.ghost_total = sums[2];
  stats.work_mean = stats.work_total / ranks;
  stats.work_imbalance = stats.work_total > 0 ? stats.work_max / stats.work_mean : 1.0;
  timers::add("ntree::distribute", stats.time_total);
  return stats;
}

template<int D>
std::vector<std::vector<std::size_t>> ntree<D>::find_ghost_sends(std::size_t& branch_count) {
  const std::size_t n = owned_size();
  if (runtime::size() == 1) {  // nobody to share with (periodic images are found locally)
    branch_count = 0;
    branches_.assign(1, {});
    return {{}};
  }
  // Owned particles are sorted by (key, id): the owned tree is built on the fields themselves.
  hashed_tree<D> owned_tree;
  tree_options options;
  options.bucket_size = config_.bucket_size;
  owned_tree.build(values<key_type>(key).view().data(), values<point<D>>(position).view().data(),
                   values<double>(mass).view().data(), values<double>(smoothing_length).view().data(), n, options);
  const auto mine = top_branches(owned_tree, config_.branch_count, config_.support, config_.ghost_reach_factor);
  branch_count = mine.size();
  branches_ = share_branches(mine, runtime::communicator());
  return shared_particles(owned_tree, space_, branches_, runtime::rank(), config_.support, config_.ghost_reach_factor);
}

template<int D>
void ntree<D>::build_local_tree() {
  tree_options options;
  options.bucket_size = config_.bucket_size;
  // Owned particles, then one block per source rank: each in (key, id) order.
  std::vector<std::size_t> runs{0};
  for (const auto& peer : this->plan().peers)
    if (peer.receive_count) runs.push_back(owned_size() + peer.receive_first);
  execute<detail::build_tree<D>>(local_, runs, options, key(*this), id(*this), position(*this), mass(*this),
                                 smoothing_length(*this))
    .wait();
}

template<int D>
void ntree<D>::refresh_local_tree() {
  execute<detail::refit<D>>(local_, position(*this), mass(*this), smoothing_length(*this));
}

}  // namespace flecsi_lite::topology::ntree
