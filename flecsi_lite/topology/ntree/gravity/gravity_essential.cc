// The locally essential tree of the distributed gravity walk (Salmon 1991; Warren & Salmon 1993):
// each rank walks the other ranks' target groups over its own subtrees with the walk's opening
// test and returns what those walks reach (one MPI_Alltoallv); the receiver links it below the
// shared top tree, next to its own local tree.
#include "flecsi_lite/topology/ntree/gravity/detail/gravity_top_tree.hh"

#include "flecsi_lite/execution/forall.hh"
#include "flecsi_lite/runtime/context.hh"
#include "flecsi_lite/topology/ntree/gravity/detail/gravity_opening.hh"

#include <algorithm>
#include <atomic>
#include <climits>
#include <cstring>
#include <memory>
#include <stdexcept>

namespace flecsi_lite::topology::ntree::detail {
namespace {

// Marks the nodes of `local` that the walk of `group` opens (not accepted, all ancestors opened),
// going down from the top tree's root into this rank's own subtrees only: the same decisions,
// on the same data, as gravity_walk's list builder on the global tree.
template<int D>
void mark_opened(const top_tree<D>& top, const hashed_tree<D>& local, const group_record<D>& group,
                 const gravity_options& options, int rank, std::atomic<std::uint8_t>* opened,
                 std::vector<std::uint64_t>& stack) {
  // An entry is a top index, or a local index with the high bit set.
  constexpr std::uint64_t local_bit = std::uint64_t{1} << 63;
  stack.assign(1, 0);
  while (!stack.empty()) {
    const std::uint64_t entry = stack.back();
    stack.pop_back();
    std::uint32_t here = hashed_tree<D>::npos;
    if (entry & local_bit) {
      here = static_cast<std::uint32_t>(entry & ~local_bit);
      if (gravity_accepts<D>(local.node(here), group, options)) continue;
    } else {
      const tree_node<D>& node = top.nodes[entry];
      if (node.size() == 0 || gravity_accepts<D>(node, group, options)) continue;
      if (top.owner[entry] == -1) {
        for (std::uint32_t c = node.first_child + node.child_count; c-- > node.first_child;) stack.push_back(c);
        continue;
      }
      if (top.owner[entry] != rank) continue;
      here = top.local[entry];
    }
    opened[here].store(1, std::memory_order_relaxed);
    const tree_node<D>& node = local.node(here);
    for (std::uint32_t c = node.first_child + node.child_count; c-- > node.first_child;) stack.push_back(local_bit | c);
  }
}

template<class T>
void append_bytes(std::vector<std::byte>& out, const T* values, std::size_t count) {
  const std::size_t at = out.size();
  out.resize(at + count * sizeof(T));
  if (count) std::memcpy(out.data() + at, values, count * sizeof(T));
}

template<class T>
std::vector<T> read_bytes(const std::byte*& in, std::size_t count) {
  std::vector<T> values(count);
  if (count) std::memcpy(values.data(), in, count * sizeof(T));
  in += count * sizeof(T);
  return values;
}

// The reply to one rank: the opened subtree roots (top indices), then breadth first from them
// the children of every opened node (with `opened` set where the receiver's walks go on) and the
// particles of every opened leaf.
template<int D>
void encode_reply(const top_tree<D>& top, const hashed_tree<D>& local, const std::vector<std::uint32_t>& roots,
                  const std::atomic<std::uint8_t>* opened, bool with_quadrupoles, int rank,
                  std::vector<std::byte>& out) {
  std::vector<std::uint64_t> opened_roots;
  std::vector<std::uint32_t> queue;
  for (const std::uint32_t t : roots)
    if (opened[top.local[t]].load(std::memory_order_relaxed)) {
      opened_roots.push_back(t);
      queue.push_back(top.local[t]);
    }
  std::vector<wire_node<D>> nodes;
  std::vector<wire_particle<D>> particles;
  for (std::size_t at = 0; at < queue.size(); ++at) {
    const tree_node<D>& node = local.node(queue[at]);
    if (node.is_leaf()) {
      for (std::uint32_t b = node.begin; b < node.end; ++b)
        particles.push_back({node.key, local.positions()[b], local.masses()[b], local.smoothing_lengths()[b]});
      continue;
    }
    for (std::uint32_t c = node.first_child; c < node.first_child + node.child_count; ++c) {
      wire_node<D> record = to_wire<D>(local.node(c), with_quadrupoles ? &local.node_quadrupole(c) : nullptr, rank);
      record.opened = opened[c].load(std::memory_order_relaxed);
      nodes.push_back(record);
      if (record.opened) queue.push_back(c);
    }
  }
  const std::uint64_t header[3] = {opened_roots.size(), nodes.size(), particles.size()};
  append_bytes(out, header, 3);
  append_bytes(out, opened_roots.data(), opened_roots.size());
  append_bytes(out, nodes.data(), nodes.size());
  append_bytes(out, particles.data(), particles.size());
}

// Links one rank's reply below the opened subtree roots of `out` (the top tree's indices are
// `out`'s first ones), in the order it was encoded.
template<int D>
void decode_reply(const std::byte* in, bool with_quadrupoles, essential_sources<D>& out) {
  std::uint64_t header[3];
  std::memcpy(header, in, sizeof(header));
  in += sizeof(header);
  const auto roots = read_bytes<std::uint64_t>(in, header[0]);
  const auto nodes = read_bytes<wire_node<D>>(in, header[1]);
  const auto particles = read_bytes<wire_particle<D>>(in, header[2]);
  out.imported_nodes += nodes.size();
  out.imported_particles += particles.size();
  // (assembled index, its children in T): children 0 for a leaf, whose particles follow.
  std::vector<std::pair<std::size_t, std::uint8_t>> queue;
  for (const std::uint64_t t : roots) queue.emplace_back(t, out.nodes[t].child_count);
  std::size_t next_node = 0, next_particle = 0;
  for (std::size_t at = 0; at < queue.size(); ++at) {
    const auto [index, children] = queue[at];
    if (children == 0) {
      const std::uint32_t size = out.nodes[index].size();
      out.nodes[index].begin = static_cast<std::uint32_t>(out.x.size());
      out.nodes[index].end = out.nodes[index].begin + size;
      for (std::uint32_t k = 0; k < size; ++k, ++next_particle) {
        out.x.push_back(particles[next_particle].x);
        out.m.push_back(particles[next_particle].m);
        out.h.push_back(particles[next_particle].h);
      }
      continue;
    }
    out.nodes[index].first_child = static_cast<std::uint32_t>(out.nodes.size());
    out.nodes[index].child_count = children;
    for (std::uint8_t c = 0; c < children; ++c, ++next_node) {
      const wire_node<D>& record = nodes[next_node];
      quadrupole<D> q = quadrupole<D>::Zero();
      tree_node<D> node = from_wire<D>(record, &q);
      // Not opened: no walk of this rank opens it (each accepts it), so it needs no children.
      node.child_count = 0;
      if (record.opened) queue.emplace_back(out.nodes.size(), record.child_count);
      out.nodes.push_back(node);
      if (with_quadrupoles) out.quadrupoles.push_back(q);
    }
  }
  if (next_node != nodes.size() || next_particle != particles.size())
    throw std::logic_error("ntree gravity tree: an essential-tree reply does not match its header");
}

int checked_int(std::size_t value) {
  if (value > static_cast<std::size_t>(INT_MAX))
    throw std::length_error("ntree gravity tree: an essential-tree message exceeds 2 GiB");
  return static_cast<int>(value);
}

// Collective: sends outgoing[r] to every rank r (one MPI_Alltoall of counts, one MPI_Alltoallv
// of bytes); returns what came, source rank after source rank, `counts` records from each.
template<class T>
std::vector<T> exchange_records(const std::vector<std::vector<T>>& outgoing, MPI_Comm comm, std::vector<int>& counts) {
  const int size = static_cast<int>(outgoing.size());
  std::vector<int> send_bytes(size), send_offsets(size), receive_bytes(size), receive_offsets(size);
  std::vector<std::byte> send;
  for (int r = 0; r < size; ++r) {
    send_offsets[r] = checked_int(send.size());
    append_bytes(send, outgoing[r].data(), outgoing[r].size());
    send_bytes[r] = checked_int(send.size()) - send_offsets[r];
  }
  runtime::check_mpi(MPI_Alltoall(send_bytes.data(), 1, MPI_INT, receive_bytes.data(), 1, MPI_INT, comm),
                     "ntree gravity tree: group counts");
  std::size_t total = 0;
  counts.resize(size);
  for (int r = 0; r < size; ++r) {
    receive_offsets[r] = checked_int(total);
    total += static_cast<std::size_t>(receive_bytes[r]);
    counts[r] = receive_bytes[r] / static_cast<int>(sizeof(T));
  }
  std::vector<T> received(total / sizeof(T));
  runtime::check_mpi(MPI_Alltoallv(send.data(), send_bytes.data(), send_offsets.data(), MPI_BYTE, received.data(),
                                   receive_bytes.data(), receive_offsets.data(), MPI_BYTE, comm),
                     "ntree gravity tree: groups");
  return received;
}

}  // namespace

template<int D>
void assemble_essential_tree(const top_tree<D>& top, const hashed_tree<D>& local,
                             const std::vector<target_group<D>>& groups, const gravity_options& options, int rank,
                             MPI_Comm comm, essential_sources<D>& out) {
  int size = 1;
  MPI_Comm_size(comm, &size);
  const bool with_quadrupoles = options.quadrupole;
  // Each group goes only to the ranks owning a subtree root that its walk over the top tree
  // (the same on every rank) reaches and opens: no other rank has anything it needs.
  std::vector<std::vector<int>> needed_by(groups.size());
  flecsi_lite::forall(
    groups.size(),
    [&](std::size_t g) {
      const group_record<D> group{groups[g].bounds, groups[g].h_max, groups[g].acceleration_min};
      thread_local std::vector<std::uint32_t> stack;
      stack.assign(top.nodes.empty() ? 0 : 1, 0);
      while (!stack.empty()) {
        const std::uint32_t t = stack.back();
        stack.pop_back();
        const tree_node<D>& node = top.nodes[t];
        if (node.size() == 0 || gravity_accepts<D>(node, group, options)) continue;
        if (top.owner[t] == -1) {
          for (std::uint32_t c = node.first_child + node.child_count; c-- > node.first_child;) stack.push_back(c);
        } else if (top.owner[t] != rank) {
          needed_by[g].push_back(top.owner[t]);
        }
      }
      std::sort(needed_by[g].begin(), needed_by[g].end());
      needed_by[g].erase(std::unique(needed_by[g].begin(), needed_by[g].end()), needed_by[g].end());
    },
    "ntree::gravity_tree::group_destinations", flecsi_lite::dynamic_schedule{});
  std::vector<std::vector<group_record<D>>> outgoing(size);
  for (std::size_t g = 0; g < groups.size(); ++g)
    for (const int r : needed_by[g])
      outgoing[r].push_back({groups[g].bounds, groups[g].h_max, groups[g].acceleration_min});
  std::vector<int> group_counts;
  const auto all_groups = exchange_records(outgoing, comm, group_counts);
  out.sent_groups = 0;
  for (const auto& list : outgoing) out.sent_groups += list.size();

  // Replies: for every other rank, what its groups' walks reach in this rank's subtrees.
  std::vector<std::uint32_t> roots;
  for (std::uint32_t t = 0; t < top.nodes.size(); ++t)
    if (top.owner[t] == rank) roots.push_back(t);
  const std::size_t local_nodes = local.nodes().size();
  std::unique_ptr<std::atomic<std::uint8_t>[]> opened(new std::atomic<std::uint8_t>[local_nodes]);
  std::vector<std::byte> send;
  std::vector<int> send_counts(size, 0), send_offsets(size, 0);
  for (int s = 0, first = 0; s < size; first += group_counts[s], ++s) {
    send_offsets[s] = checked_int(send.size());
    if (s == rank || roots.empty() || group_counts[s] == 0) continue;
    for (std::size_t i = 0; i < local_nodes; ++i) opened[i].store(0, std::memory_order_relaxed);
    const group_record<D>* theirs = all_groups.data() + first;
    flecsi_lite::forall(
      static_cast<std::size_t>(group_counts[s]),
      [&](std::size_t g) {
        thread_local std::vector<std::uint64_t> stack;
        mark_opened<D>(top, local, theirs[g], options, rank, opened.get(), stack);
      },
      "ntree::gravity_tree::essential", flecsi_lite::dynamic_schedule{});
    encode_reply<D>(top, local, roots, opened.get(), with_quadrupoles, rank, send);
    send_counts[s] = checked_int(send.size()) - send_offsets[s];
  }
  std::vector<int> receive_counts(size), receive_offsets(size);
  runtime::check_mpi(MPI_Alltoall(send_counts.data(), 1, MPI_INT, receive_counts.data(), 1, MPI_INT, comm),
                     "ntree gravity tree: reply sizes");
  std::size_t total = 0;
  for (int r = 0; r < size; ++r) {
    receive_offsets[r] = checked_int(total);
    total += static_cast<std::size_t>(receive_counts[r]);
  }
  std::vector<std::byte> received(total);
  runtime::check_mpi(MPI_Alltoallv(send.data(), send_counts.data(), send_offsets.data(), MPI_BYTE, received.data(),
                                   receive_counts.data(), receive_offsets.data(), MPI_BYTE, comm),
                     "ntree gravity tree: replies");

  // The source tree: the top tree (straddling leaves' particles after the owned ones), this
  // rank's local tree below its subtree roots, then the imports below the others'.
  const std::size_t owned = local.size();
  const std::size_t sent_groups = out.sent_groups;
  out = essential_sources<D>{};
  out.sent_groups = sent_groups;
  out.nodes = top.nodes;
  if (with_quadrupoles) out.quadrupoles = top.quadrupoles;
  out.x.assign(local.positions(), local.positions() + owned);
  out.m.assign(local.masses(), local.masses() + owned);
  out.h.assign(local.smoothing_lengths(), local.smoothing_lengths() + owned);
  out.x.insert(out.x.end(), top.x.begin(), top.x.end());
  out.m.insert(out.m.end(), top.m.begin(), top.m.end());
  out.h.insert(out.h.end(), top.h.begin(), top.h.end());
  out.imported_nodes = top.nodes_from_others;
  out.imported_particles = top.particles_from_others;
  const auto offset = static_cast<std::uint32_t>(top.nodes.size());
  for (std::size_t t = 0; t < top.nodes.size(); ++t) {
    tree_node<D>& node = out.nodes[t];
    if (top.owner[t] == -1) {
      if (node.is_leaf()) {
        node.begin += static_cast<std::uint32_t>(owned);
        node.end += static_cast<std::uint32_t>(owned);
      }
    } else if (top.owner[t] == rank) {
      node = local.node(top.local[t]);
      node.first_child += offset;
    }
  }
  for (std::uint32_t i = 0; i < local_nodes; ++i) {
    tree_node<D> node = local.node(i);
    node.first_child += offset;
    out.nodes.push_back(node);
    if (with_quadrupoles) out.quadrupoles.push_back(local.node_quadrupole(i));
  }
  // The others' subtree roots keep their children count until their owner's reply links them;
  // those no walk here opens become childless (they are accepted wherever reached).
  std::vector<std::uint8_t> children(top.nodes.size());
  for (std::size_t t = 0; t < top.nodes.size(); ++t)
    if (top.owner[t] != -1 && top.owner[t] != rank) {
      children[t] = out.nodes[t].child_count;
      out.nodes[t].child_count = 0;
    }
  for (int r = 0; r < size; ++r) {
    if (receive_counts[r] == 0) continue;
    const std::byte* in = received.data() + receive_offsets[r];
    std::uint64_t root_count = 0;
    std::memcpy(&root_count, in, sizeof(root_count));
    std::vector<std::uint64_t> roots_of_r(root_count);
    std::memcpy(roots_of_r.data(), in + 3 * sizeof(std::uint64_t), root_count * sizeof(std::uint64_t));
    for (const std::uint64_t t : roots_of_r) out.nodes[t].child_count = children[t];
    decode_reply<D>(in, with_quadrupoles, out);
  }
}

#define FLECSI_LITE_GRAVITY_ESSENTIAL(D)                                                                               \
  template void assemble_essential_tree<D>(const top_tree<D>&, const hashed_tree<D>&,                                  \
                                           const std::vector<target_group<D>>&, const gravity_options&, int, MPI_Comm, \
                                           essential_sources<D>&);
FLECSI_LITE_GRAVITY_ESSENTIAL(1)
FLECSI_LITE_GRAVITY_ESSENTIAL(2)
FLECSI_LITE_GRAVITY_ESSENTIAL(3)
#undef FLECSI_LITE_GRAVITY_ESSENTIAL

}  // namespace flecsi_lite::topology::ntree::detail
