// Sender-driven ghost plans and the all-fields ghost copy used when the ntree topology builds
// its ghosts (later copies of single fields go through the executor with the same plan).
#include "flecsi_lite/topology/ntree/distributed/ghost_exchange.hh"

#include "flecsi_lite/runtime/context.hh"

#include <climits>
#include <stdexcept>

namespace flecsi_lite::topology::ntree {
namespace {
int checked_int(std::size_t value) {
  if (value > static_cast<std::size_t>(INT_MAX))
    throw std::length_error("ntree ghost exchange: too many bytes for one MPI call");
  return static_cast<int>(value);
}
} // namespace

data::ghost_plan build_sender_plan(std::vector<std::vector<std::size_t>> send_to, MPI_Comm comm) {
  int size = 1;
  MPI_Comm_size(comm, &size);
  if (send_to.size() != static_cast<std::size_t>(size))
    throw std::invalid_argument("build_sender_plan: one send list per rank is needed");
  std::vector<int> sending(size), receiving(size);
  for (int r = 0; r < size; ++r) sending[r] = checked_int(send_to[r].size());
  runtime::check_mpi(MPI_Alltoall(sending.data(), 1, MPI_INT, receiving.data(), 1, MPI_INT, comm),
                     "ntree ghost plan: counts");
  data::ghost_plan plan;
  std::size_t slot = 0;
  for (int r = 0; r < size; ++r) {
    if (sending[r] == 0 && receiving[r] == 0) continue;
    data::ghost_plan::peer peer;
    peer.rank = r;
    peer.send = std::move(send_to[r]);
    peer.receive_first = slot;
    peer.receive_count = static_cast<std::size_t>(receiving[r]);
    slot += peer.receive_count;
    plan.peers.push_back(std::move(peer));
  }
  return plan;
}

std::size_t ghost_count(const data::ghost_plan& plan) {
  std::size_t total = 0;
  for (const auto& peer : plan.peers) total += peer.receive_count;
  return total;
}

void copy_to_ghosts(const data::ghost_plan& plan, const std::vector<data::field_storage_base*>& fields,
                    std::size_t owned_size, MPI_Comm comm) {
  int size = 1;
  MPI_Comm_size(comm, &size);
  std::size_t per_particle = 0;
  for (const auto* f : fields) per_particle += f->element_size();

  std::vector<int> send_counts(size, 0), send_offsets(size, 0), receive_counts(size, 0),
    receive_offsets(size, 0);
  std::size_t send_total = 0, receive_total = 0;
  for (const auto& peer : plan.peers) {
    send_counts[peer.rank] = checked_int(peer.send.size() * per_particle);
    receive_counts[peer.rank] = checked_int(peer.receive_count * per_particle);
  }
  for (int r = 0; r < size; ++r) {
    send_offsets[r] = checked_int(send_total);
    receive_offsets[r] = checked_int(receive_total);
    send_total += static_cast<std::size_t>(send_counts[r]);
    receive_total += static_cast<std::size_t>(receive_counts[r]);
  }
  std::vector<std::byte> send(send_total), receive(receive_total);
  for (const auto& peer : plan.peers) {
    std::byte* out = send.data() + send_offsets[peer.rank];
    for (const auto* f : fields) {
      f->pack(peer.send.data(), peer.send.size(), out);
      out += peer.send.size() * f->element_size();
    }
  }
  runtime::check_mpi(MPI_Alltoallv(send.data(), send_counts.data(), send_offsets.data(), MPI_BYTE,
                                   receive.data(), receive_counts.data(), receive_offsets.data(), MPI_BYTE,
                                   comm),
                     "ntree ghost exchange");
  for (const auto& peer : plan.peers) {
    const std::byte* in = receive.data() + receive_offsets[peer.rank];
    for (auto* f : fields) {
      f->unpack(in, owned_size + peer.receive_first, peer.receive_count);
      in += peer.receive_count * f->element_size();
    }
  }
}

} // namespace flecsi_lite::topology::ntree
