// The start of a ghost copy (detail/ghost_copy.hh): pack every field's shared values into one
// buffer per peer, post one receive and one send per peer; the finish unpacks per field. A field's
// part of a message is a mask of its entities and the values of the marked ones: those whose bits
// changed since the field's last copy to that peer (every one when the peer's ghosts may hold
// something else). A ghost reduction sends the same messages the other way, whole.
#include "flecsi_lite/execution/detail/ghost_copy.hh"

#include "flecsi_lite/execution/executor.hh"
#include "flecsi_lite/runtime/context.hh"

#include <cstdint>
#include <memory>

namespace flecsi_lite::execution::detail {
namespace {
// A message's bytes, not zeroed when allocated: every byte sent is written first, and a receive
// is filled by MPI (zeroing megabytes per copy showed as 2% of a two-rank run).
template<class T>
struct uninitialized_allocator : std::allocator<T> {
  template<class U>
  struct rebind {
    using other = uninitialized_allocator<U>;
  };
  uninitialized_allocator() = default;
  template<class U>
  uninitialized_allocator(const uninitialized_allocator<U>&) {}
  template<class U>
  void construct(U* p) {
    ::new (static_cast<void*>(p)) U;  // default-initialized: no value for std::byte
  }
};
using message = std::vector<std::byte, uninitialized_allocator<std::byte>>;
using messages = std::vector<message>;

// One message each way with `peer`: the launch completes when both requests have. `receive` has
// room for the largest message (the caller counts the bytes received).
void post_exchange(launch& self, int peer, message& send, message& receive, int tag, ghost_traffic& traffic) {
  MPI_Request requests[2];
  MPI_Irecv(receive.data(), static_cast<int>(receive.size()), MPI_BYTE, peer, tag, runtime::communicator(),
            &requests[0]);
  MPI_Isend(send.data(), static_cast<int>(send.size()), MPI_BYTE, peer, tag, runtime::communicator(), &requests[1]);
  self.requests.insert(self.requests.end(), requests, requests + 2);
  ++traffic.messages_sent;
  traffic.bytes_sent += send.size();
  ++traffic.messages_received;
}

// The bytes of one field's part of a message to or from a peer of `count` entities: its mask,
// then at most every value.
std::size_t mask_bytes(std::size_t count) { return (count + 7) / 8; }
std::size_t largest_part(const copied_field& f, std::size_t count) {
  return mask_bytes(count) + count * f.storage->element_size();
}

// Whether the values `f` sent to peer `p` in its last copy are still what that peer's ghosts
// hold: no launch wrote them since (record order, the same on every rank) and there was a last
// copy (the executor starts a field's record afresh at every layout change).
bool receivers_hold_sent(const copied_field& f, std::size_t p, std::size_t count) {
  const sent_ghost_values& sent = *f.sent;
  return f.receivers_hold_sent && p < sent.per_peer.size() &&
         sent.per_peer[p].size() == count * f.storage->element_size();
}
}  // namespace

std::function<void(launch&)> ghost_copy_start(data::topology_base* topology, std::vector<copied_field> fields, int tag,
                                              ghost_traffic* traffic) {
  auto receive_buffers = std::make_shared<messages>();
  return [topology, fields, tag, receive_buffers, traffic](launch& self) {
    const auto& peers = topology->plan().peers;
    const std::size_t ghost_begin = topology->owned_size();
    const int me = runtime::rank();
    std::vector<data::field_storage_base*> storages;
    for (const auto& f : fields) storages.push_back(f.storage);
    receive_buffers->assign(peers.size(), {});
    // Send buffers must live until the sends complete: keep them with the receive buffers.
    auto send_buffers = std::make_shared<messages>(peers.size());
    for (std::size_t p = 0; p < peers.size(); ++p) {
      const auto& peer = peers[p];
      auto& send = (*send_buffers)[p];
      if (peer.rank == me) {  // periodic images of this rank's own entities: every value, in place
        std::size_t bytes = 0;
        for (auto* s : storages) bytes += s->element_size();
        send.resize(peer.send.size() * bytes);
        data::pack_fields(storages, peer.send, send.data());
        data::unpack_fields(storages, send.data(), ghost_begin + peer.receive_first, peer.receive_count);
        continue;
      }
      std::size_t largest = 0, largest_received = 0;
      for (const auto& f : fields) {
        largest += largest_part(f, peer.send.size());
        largest_received += largest_part(f, peer.receive_count);
      }
      send.resize(largest);
      std::byte* out = send.data();
      for (const auto& f : fields) {
        auto& sent = *f.sent;
        const bool compare = receivers_hold_sent(f, p, peer.send.size());
        if (sent.per_peer.size() != peers.size()) sent.per_peer.resize(peers.size());
        sent.per_peer[p].resize(peer.send.size() * f.storage->element_size());
        auto* mask = reinterpret_cast<std::uint8_t*>(out);
        out += mask_bytes(peer.send.size());
        out += f.storage->pack_changed(peer.send.data(), peer.send.size(), compare, sent.per_peer[p].data(), mask, out);
      }
      send.resize(std::size_t(out - send.data()));
      auto& receive = (*receive_buffers)[p];
      receive.resize(largest_received);
      post_exchange(self, peer.rank, send, receive, tag, *traffic);
    }
    self.finish = [topology, storages, receive_buffers, send_buffers, me, traffic] {
      const auto& finished_peers = topology->plan().peers;
      const std::size_t begin = topology->owned_size();
      for (std::size_t p = 0; p < finished_peers.size(); ++p) {
        const auto& peer = finished_peers[p];
        if (peer.rank == me) continue;
        const std::byte* const message = (*receive_buffers)[p].data();
        const std::byte* in = message;
        for (auto* s : storages) {
          const auto* mask = reinterpret_cast<const std::uint8_t*>(in);
          in += mask_bytes(peer.receive_count);
          in += s->unpack_marked(mask, in, begin + peer.receive_first, peer.receive_count);
        }
        traffic->bytes_received += std::size_t(in - message);
      }
    };
  };
}

std::function<void(launch&)> ghost_reduction_start(data::topology_base* topology, data::field_storage_base* storage,
                                                   combine_into_owned combine, int tag, ghost_traffic* traffic) {
  auto receive_buffers = std::make_shared<messages>();
  return [topology, storage, combine, tag, receive_buffers, traffic](launch& self) {
    const auto& peers = topology->plan().peers;
    const std::size_t ghost_begin = topology->owned_size(), bytes = storage->element_size();
    const int me = runtime::rank();
    receive_buffers->assign(peers.size(), {});
    auto send_buffers = std::make_shared<messages>(peers.size());
    for (std::size_t p = 0; p < peers.size(); ++p) {
      const auto& peer = peers[p];
      auto& send = (*send_buffers)[p];
      send.resize(peer.receive_count * bytes);
      storage->pack_range(ghost_begin + peer.receive_first, peer.receive_count, send.data());
      if (peer.rank == me) continue;  // periodic images of this rank's own entities: combined as they are
      auto& receive = (*receive_buffers)[p];
      receive.resize(peer.send.size() * bytes);
      traffic->bytes_received += receive.size();
      post_exchange(self, peer.rank, send, receive, tag, *traffic);
    }
    // In rank order, so that a sum is the same from run to run.
    self.finish = [topology, combine, receive_buffers, send_buffers, me] {
      const auto& finished_peers = topology->plan().peers;
      for (std::size_t p = 0; p < finished_peers.size(); ++p)
        combine(finished_peers[p].send,
                (finished_peers[p].rank == me ? (*send_buffers)[p] : (*receive_buffers)[p]).data());
    };
  };
}

void report_ghost_traffic(const ghost_traffic& traffic, std::ostream& out) {
  const double mine[2] = {double(traffic.messages_sent), double(traffic.bytes_sent)};
  double lo[2], hi[2], sum[2];
  MPI_Allreduce(mine, lo, 2, MPI_DOUBLE, MPI_MIN, runtime::communicator());
  MPI_Allreduce(mine, hi, 2, MPI_DOUBLE, MPI_MAX, runtime::communicator());
  MPI_Allreduce(mine, sum, 2, MPI_DOUBLE, MPI_SUM, runtime::communicator());
  if (runtime::rank() != 0) return;
  const double ranks = runtime::size();
  out << "Ghost copies per rank (min / mean / max over " << runtime::size() << " ranks): messages sent " << lo[0]
      << " / " << sum[0] / ranks << " / " << hi[0] << ", bytes sent " << lo[1] << " / " << sum[1] / ranks << " / "
      << hi[1] << "\n";
}

}  // namespace flecsi_lite::execution::detail
