// The shared top of the distributed gravity tree (locally essential trees, Warren & Salmon 1993):
// the cells straddling rank boundaries from an allgather of the ranks' end keys, their global
// counts, the top tree every rank computes identically, and the target groups of the global tree.
#include "flecsi_lite/topology/ntree/gravity/detail/gravity_top_tree.hh"

#include "flecsi_lite/runtime/context.hh"
#include "flecsi_lite/topology/ntree/detail/node_moments.hh"

#include <algorithm>
#include <climits>
#include <cstring>
#include <limits>
#include <numeric>
#include <stdexcept>

namespace flecsi_lite::topology::ntree::detail {

template<class T>
std::vector<T> allgather_records(const std::vector<T>& mine, MPI_Comm comm, std::vector<int>* counts) {
  int size = 1;
  MPI_Comm_size(comm, &size);
  if (mine.size() * sizeof(T) > static_cast<std::size_t>(INT_MAX))
    throw std::length_error("ntree gravity tree: a rank's records exceed 2 GiB");
  const int my_bytes = static_cast<int>(mine.size() * sizeof(T));
  std::vector<int> bytes(size), offsets(size);
  runtime::check_mpi(MPI_Allgather(&my_bytes, 1, MPI_INT, bytes.data(), 1, MPI_INT, comm),
                     "ntree gravity tree: record counts");
  std::size_t total = 0;
  for (int r = 0; r < size; ++r) {
    offsets[r] = static_cast<int>(total);
    total += static_cast<std::size_t>(bytes[r]);
  }
  if (total > static_cast<std::size_t>(INT_MAX))
    throw std::length_error("ntree gravity tree: the gathered records exceed 2 GiB");
  std::vector<T> all(total / sizeof(T));
  runtime::check_mpi(
    MPI_Allgatherv(mine.data(), my_bytes, MPI_BYTE, all.data(), bytes.data(), offsets.data(), MPI_BYTE, comm),
    "ntree gravity tree: records");
  if (counts) {
    counts->resize(size);
    for (int r = 0; r < size; ++r) (*counts)[r] = bytes[r] / static_cast<int>(sizeof(T));
  }
  return all;
}

namespace {
struct key_span {
  key_type first = 0, last = 0;
  std::uint64_t count = 0;
};

// The common ancestors of two full-depth keys: their deepest common cell and all above it.
template<int D>
void add_common_ancestors(key_type a, key_type b, std::vector<key_type>& out) {
  key_type common = a;
  if (a != b) {
    const int top_bit = 63 - __builtin_clzll(a ^ b);
    common = a >> (D * (top_bit / D + 1));
  }
  for (; common >= root_key; common >>= D) {
    out.push_back(common);
    if (common == root_key) break;
  }
}
}  // namespace

template<int D>
void straddling_cells::find(const key_type* keys, const double* acceleration_old, std::size_t n,
                            std::size_t bucket_size, MPI_Comm comm) {
  cells_.clear();
  const key_span mine{n ? keys[0] : 0, n ? keys[n - 1] : 0, n};
  const std::vector<key_span> spans = allgather_records(std::vector<key_span>{mine}, comm);
  std::vector<key_type> found;
  const key_span* previous = nullptr;
  for (const key_span& span : spans) {
    if (span.count == 0) continue;
    if (previous) add_common_ancestors<D>(previous->last, span.first, found);
    previous = &span;
  }
  std::sort(found.begin(), found.end());
  found.erase(std::unique(found.begin(), found.end()), found.end());

  // This rank's share of each cell: its particles before the cell, in it, and their smallest
  // |a_old| (+inf: none here; 0 without old accelerations, as target_groups has it).
  const std::size_t count = found.size();
  std::vector<std::uint64_t> local(2 * count), global(2 * count);
  std::vector<double> smallest(count, std::numeric_limits<double>::infinity()), global_smallest(count);
  for (std::size_t i = 0; i < count; ++i) {
    const int below = D * (max_level<D> - level<D>(found[i]));
    const key_type first = found[i] << below;
    const key_type last = first | ((key_type{1} << below) - 1);
    const std::size_t begin = static_cast<std::size_t>(std::lower_bound(keys, keys + n, first) - keys);
    const std::size_t end = static_cast<std::size_t>(std::upper_bound(keys + begin, keys + n, last) - keys);
    local[i] = begin;
    local[count + i] = end - begin;
    if (end > begin) {
      smallest[i] = acceleration_old ? *std::min_element(acceleration_old + begin, acceleration_old + end) : 0.0;
    }
  }
  runtime::check_mpi(
    MPI_Allreduce(local.data(), global.data(), static_cast<int>(2 * count), MPI_UINT64_T, MPI_SUM, comm),
    "ntree gravity tree: straddling counts");
  runtime::check_mpi(
    MPI_Allreduce(smallest.data(), global_smallest.data(), static_cast<int>(count), MPI_DOUBLE, MPI_MIN, comm),
    "ntree gravity tree: straddling accelerations");
  cells_.resize(count);
  for (std::size_t i = 0; i < count; ++i) {
    straddling_cell& cell = cells_[i];
    cell.key = found[i];
    cell.begin = global[i];
    cell.count = global[count + i];
    cell.acceleration_min = global_smallest[i];
  }
  for (straddling_cell& cell : cells_) {
    // Sorted keys put parents first; the parent of a straddling cell straddles too.
    cell.in_tree = cell.key == root_key || cells_[index(parent<D>(cell.key))].split;
    cell.split = cell.in_tree && cell.count > bucket_size && level<D>(cell.key) < max_level<D>;
  }
}

std::size_t straddling_cells::index(key_type key) const {
  const auto at =
    std::lower_bound(cells_.begin(), cells_.end(), key, [](const straddling_cell& c, key_type k) { return c.key < k; });
  return at != cells_.end() && at->key == key ? static_cast<std::size_t>(at - cells_.begin()) : npos;
}

template<int D>
wire_node<D> to_wire(const tree_node<D>& node, const quadrupole<D>* q, int owner) {
  wire_node<D> record;
  record.key = node.key;
  record.bounds = node.bounds;
  record.centre = node.centre;
  record.h_max = node.h_max;
  record.mass = node.mass;
  if (q) std::memcpy(record.q.data(), q->data(), sizeof(record.q));
  record.size = node.size();
  record.owner = owner;
  record.level = node.level;
  record.child_count = node.child_count;
  return record;
}

template<int D>
tree_node<D> from_wire(const wire_node<D>& record, quadrupole<D>* q) {
  tree_node<D> node;
  node.key = record.key;
  node.begin = 0;
  node.end = record.size;
  node.child_count = record.child_count;
  node.level = record.level;
  node.bounds = record.bounds;
  node.h_max = record.h_max;
  node.mass = record.mass;
  node.centre = record.centre;
  if (q) std::memcpy(q->data(), record.q.data(), sizeof(record.q));
  return node;
}

template<int D>
top_tree<D> build_top_tree(const hashed_tree<D>& local, const straddling_cells& cells, bool with_quadrupoles, int rank,
                           MPI_Comm comm) {
  const auto quadrupole_of = [&](std::uint32_t i) { return with_quadrupoles ? &local.node_quadrupole(i) : nullptr; };
  // What this rank knows of the top: its children of split straddling nodes that do not
  // straddle (so are all here), and its particles of straddling leaves.
  std::vector<wire_node<D>> my_nodes;
  std::vector<wire_particle<D>> my_particles;
  if (cells.empty()) {
    if (local.size() > 0) my_nodes.push_back(to_wire<D>(local.root(), quadrupole_of(0), rank));
  }
  for (std::size_t i = 0; i < cells.size(); ++i) {
    const straddling_cell& cell = cells[i];
    const std::uint32_t here = cell.in_tree ? local.find(cell.key) : hashed_tree<D>::npos;
    if (here == hashed_tree<D>::npos) continue;
    const tree_node<D>& node = local.node(here);
    if (cell.split) {
      for (std::uint32_t c = node.first_child; c < node.first_child + node.child_count; ++c)
        if (cells.index(local.node(c).key) == straddling_cells::npos)
          my_nodes.push_back(to_wire<D>(local.node(c), quadrupole_of(c), rank));
    } else {
      for (std::uint32_t b = node.begin; b < node.end; ++b)
        my_particles.push_back({cell.key, local.positions()[b], local.masses()[b], local.smoothing_lengths()[b]});
    }
  }
  std::vector<int> node_counts, particle_counts;
  const auto records = allgather_records(my_nodes, comm, &node_counts);
  const auto particles = allgather_records(my_particles, comm, &particle_counts);

  top_tree<D> top;
  const auto add_record = [&](const wire_node<D>& record) {
    quadrupole<D> q = quadrupole<D>::Zero();
    top.nodes.push_back(from_wire<D>(record, &q));
    if (with_quadrupoles) top.quadrupoles.push_back(q);
    top.owner.push_back(record.owner);
    top.local.push_back(record.owner == rank ? local.find(record.key) : hashed_tree<D>::npos);
  };
  for (std::size_t r = 0; r < node_counts.size(); ++r)
    if (static_cast<int>(r) != rank) {
      top.nodes_from_others += static_cast<std::size_t>(node_counts[r]);
      top.particles_from_others += static_cast<std::size_t>(particle_counts[r]);
    }
  if (cells.empty()) {
    for (const auto& record : records) add_record(record);
    return top;
  }

  // Children of the straddling nodes: the straddling cells of T and the gathered records, in
  // key order (which is also the order of their parents' keys).
  struct entry {
    key_type key;
    std::size_t cell, record;
  };
  std::vector<entry> entries;
  for (std::size_t i = 1; i < cells.size(); ++i)
    if (cells[i].in_tree) entries.push_back({cells[i].key, i, straddling_cells::npos});
  for (std::size_t r = 0; r < records.size(); ++r) entries.push_back({records[r].key, straddling_cells::npos, r});
  std::sort(entries.begin(), entries.end(), [](const entry& a, const entry& b) { return a.key < b.key; });
  // The straddling leaves' particles, leaf by leaf, each in rank order (the global order).
  std::vector<std::size_t> by_leaf(particles.size());
  std::iota(by_leaf.begin(), by_leaf.end(), std::size_t{0});
  std::stable_sort(by_leaf.begin(), by_leaf.end(),
                   [&](std::size_t a, std::size_t b) { return particles[a].leaf < particles[b].leaf; });

  const auto add_cell = [&](std::size_t i) {
    tree_node<D> node;
    node.key = cells[i].key;
    node.level = static_cast<std::uint8_t>(level<D>(node.key));
    node.begin = static_cast<std::uint32_t>(cells[i].begin);
    node.end = static_cast<std::uint32_t>(cells[i].begin + cells[i].count);
    top.nodes.push_back(node);
    if (with_quadrupoles) top.quadrupoles.push_back(quadrupole<D>::Zero());
    top.owner.push_back(-1);
    top.local.push_back(local.find(node.key));
  };
  add_cell(0);
  std::size_t next_particle = 0;
  for (std::size_t t = 0; t < top.nodes.size(); ++t) {
    if (top.owner[t] != -1) continue;
    const std::size_t i = cells.index(top.nodes[t].key);
    if (cells[i].split) {
      const key_type key = top.nodes[t].key;
      const auto first = std::lower_bound(entries.begin(), entries.end(), key,
                                          [](const entry& e, key_type k) { return (e.key >> D) < k; });
      const auto last =
        std::upper_bound(first, entries.end(), key, [](key_type k, const entry& e) { return k < (e.key >> D); });
      top.nodes[t].first_child = static_cast<std::uint32_t>(top.nodes.size());
      top.nodes[t].child_count = static_cast<std::uint8_t>(last - first);
      for (auto e = first; e != last; ++e) {
        if (e->cell != straddling_cells::npos)
          add_cell(e->cell);
        else
          add_record(records[e->record]);
      }
    } else {
      // A leaf of T: its particles gathered in global order.
      tree_node<D>& node = top.nodes[t];
      node.begin = static_cast<std::uint32_t>(top.x.size());
      for (; next_particle < by_leaf.size() && particles[by_leaf[next_particle]].leaf == node.key; ++next_particle) {
        const wire_particle<D>& p = particles[by_leaf[next_particle]];
        top.x.push_back(p.x);
        top.m.push_back(p.m);
        top.h.push_back(p.h);
      }
      node.end = static_cast<std::uint32_t>(top.x.size());
      if (node.size() != cells[i].count)
        throw std::logic_error("ntree gravity tree: a straddling leaf's gathered particles miss its count");
    }
  }
  // Bottom-up, children after parents: the straddling nodes with hashed_tree's sums.
  for (std::size_t t = top.nodes.size(); t-- > 0;) {
    if (top.owner[t] != -1) continue;
    tree_node<D>& node = top.nodes[t];
    quadrupole<D>* q = with_quadrupoles ? &top.quadrupoles[t] : nullptr;
    if (node.is_leaf())
      compute_leaf_moments<D>(node, top.x.data(), top.m.data(), top.h.data(), q);
    else
      compute_parent_moments<D>(node, top.nodes.data(), with_quadrupoles ? top.quadrupoles.data() : nullptr, q);
  }
  return top;
}

template<int D>
std::vector<target_group<D>> essential_groups(const top_tree<D>& top, const hashed_tree<D>& local,
                                              const straddling_cells& cells, const double* acceleration_old,
                                              std::size_t group_size, int rank) {
  std::vector<target_group<D>> groups;
  const auto is_group = [group_size](const tree_node<D>& node) { return node.size() <= group_size || node.is_leaf(); };
  std::vector<std::uint32_t> stack;
  // Groups below a node of this rank's own (local = global) part of T.
  const auto walk_local = [&](std::uint32_t start) {
    stack.assign(1, start);
    while (!stack.empty()) {
      const tree_node<D>& node = local.node(stack.back());
      stack.pop_back();
      if (!is_group(node)) {
        for (std::uint32_t c = node.first_child + node.child_count; c-- > node.first_child;) stack.push_back(c);
        continue;
      }
      target_group<D> group;
      group.bounds = node.bounds;
      group.h_max = node.h_max;
      group.begin = node.begin;
      group.end = node.end;
      if (acceleration_old)
        group.acceleration_min = *std::min_element(acceleration_old + node.begin, acceleration_old + node.end);
      groups.push_back(group);
    }
  };
  if (top.nodes.empty()) {
    if (local.size() > 0) walk_local(0);
    return groups;
  }
  std::vector<std::uint32_t> top_stack{0};
  while (!top_stack.empty()) {
    const std::uint32_t t = top_stack.back();
    top_stack.pop_back();
    const tree_node<D>& node = top.nodes[t];
    if (top.owner[t] == rank) {
      walk_local(top.local[t]);
    } else if (top.owner[t] == -1) {
      if (!is_group(node)) {
        for (std::uint32_t c = node.first_child + node.child_count; c-- > node.first_child;) top_stack.push_back(c);
      } else if (top.local[t] != hashed_tree<D>::npos && local.node(top.local[t]).size() > 0) {
        // A group node straddling ranks: every rank's share walks with the node's global data
        // (an empty rank's local tree has an empty root, which is no share).
        const tree_node<D>& here = local.node(top.local[t]);
        target_group<D> group;
        group.bounds = node.bounds;
        group.h_max = node.h_max;
        group.acceleration_min = cells[cells.index(node.key)].acceleration_min;
        group.begin = here.begin;
        group.end = here.end;
        groups.push_back(group);
      }
    }
  }
  return groups;
}

#define FLECSI_LITE_GRAVITY_TOP_TREE(D)                                                                                \
  template void straddling_cells::find<D>(const key_type*, const double*, std::size_t, std::size_t, MPI_Comm);         \
  template wire_node<D> to_wire<D>(const tree_node<D>&, const quadrupole<D>*, int);                                    \
  template tree_node<D> from_wire<D>(const wire_node<D>&, quadrupole<D>*);                                             \
  template std::vector<wire_node<D>> allgather_records(const std::vector<wire_node<D>>&, MPI_Comm, std::vector<int>*); \
  template top_tree<D> build_top_tree<D>(const hashed_tree<D>&, const straddling_cells&, bool, int, MPI_Comm);         \
  template std::vector<target_group<D>> essential_groups<D>(const top_tree<D>&, const hashed_tree<D>&,                 \
                                                            const straddling_cells&, const double*, std::size_t, int);
FLECSI_LITE_GRAVITY_TOP_TREE(1)
FLECSI_LITE_GRAVITY_TOP_TREE(2)
FLECSI_LITE_GRAVITY_TOP_TREE(3)
#undef FLECSI_LITE_GRAVITY_TOP_TREE

}  // namespace flecsi_lite::topology::ntree::detail
