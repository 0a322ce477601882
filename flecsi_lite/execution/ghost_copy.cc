// The start of a ghost copy (detail/ghost_copy.hh): pack every field's shared values into one
// buffer per peer, post one receive and one send per peer; the finish unpacks per field. A ghost
// reduction sends the same messages the other way.
#include "flecsi_lite/execution/detail/ghost_copy.hh"

#include "flecsi_lite/execution/executor.hh"
#include "flecsi_lite/runtime/context.hh"

#include <memory>

namespace flecsi_lite::execution::detail {
namespace {
// One message each way with `peer`: the launch completes when both requests have.
void post_exchange(launch& self, int peer, std::vector<std::byte>& send, std::vector<std::byte>& receive, int tag,
                   ghost_traffic& traffic) {
  MPI_Request requests[2];
  MPI_Irecv(receive.data(), static_cast<int>(receive.size()), MPI_BYTE, peer, tag, runtime::communicator(),
            &requests[0]);
  MPI_Isend(send.data(), static_cast<int>(send.size()), MPI_BYTE, peer, tag, runtime::communicator(), &requests[1]);
  self.requests.insert(self.requests.end(), requests, requests + 2);
  ++traffic.messages_sent;
  traffic.bytes_sent += send.size();
  ++traffic.messages_received;
  traffic.bytes_received += receive.size();
}
}  // namespace

std::function<void(launch&)> ghost_copy_start(data::topology_base* topology,
                                              std::vector<data::field_storage_base*> storages, int tag,
                                              ghost_traffic* traffic) {
  auto receive_buffers = std::make_shared<std::vector<std::vector<std::byte>>>();
  return [topology, storages, tag, receive_buffers, traffic](launch& self) {
    const auto& peers = topology->plan().peers;
    const std::size_t ghost_begin = topology->owned_size();
    const int me = runtime::rank();
    std::size_t bytes = 0;  // of one entity, all fields
    for (auto* s : storages) bytes += s->element_size();
    receive_buffers->assign(peers.size(), {});
    // Send buffers must live until the sends complete: keep them with the receive buffers.
    auto send_buffers = std::make_shared<std::vector<std::vector<std::byte>>>(peers.size());
    for (std::size_t p = 0; p < peers.size(); ++p) {
      const auto& peer = peers[p];
      auto& send = (*send_buffers)[p];
      send.resize(peer.send.size() * bytes);
      data::pack_fields(storages, peer.send, send.data());
      if (peer.rank == me) {  // periodic images of this rank's own entities
        data::unpack_fields(storages, send.data(), ghost_begin + peer.receive_first, peer.receive_count);
        continue;
      }
      auto& receive = (*receive_buffers)[p];
      receive.resize(peer.receive_count * bytes);
      post_exchange(self, peer.rank, send, receive, tag, *traffic);
    }
    self.finish = [topology, storages, receive_buffers, send_buffers, me] {
      const auto& finished_peers = topology->plan().peers;
      const std::size_t begin = topology->owned_size();
      for (std::size_t p = 0; p < finished_peers.size(); ++p)
        if (finished_peers[p].rank != me)
          data::unpack_fields(storages, (*receive_buffers)[p].data(), begin + finished_peers[p].receive_first,
                              finished_peers[p].receive_count);
    };
  };
}

std::function<void(launch&)> ghost_reduction_start(data::topology_base* topology, data::field_storage_base* storage,
                                                   combine_into_owned combine, int tag, ghost_traffic* traffic) {
  auto receive_buffers = std::make_shared<std::vector<std::vector<std::byte>>>();
  return [topology, storage, combine, tag, receive_buffers, traffic](launch& self) {
    const auto& peers = topology->plan().peers;
    const std::size_t ghost_begin = topology->owned_size(), bytes = storage->element_size();
    const int me = runtime::rank();
    receive_buffers->assign(peers.size(), {});
    auto send_buffers = std::make_shared<std::vector<std::vector<std::byte>>>(peers.size());
    for (std::size_t p = 0; p < peers.size(); ++p) {
      const auto& peer = peers[p];
      auto& send = (*send_buffers)[p];
      send.resize(peer.receive_count * bytes);
      storage->pack_range(ghost_begin + peer.receive_first, peer.receive_count, send.data());
      if (peer.rank == me) continue;  // periodic images of this rank's own entities: combined as they are
      auto& receive = (*receive_buffers)[p];
      receive.resize(peer.send.size() * bytes);
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
