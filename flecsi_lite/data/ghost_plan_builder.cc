#include "flecsi_lite/data/ghost_plan_builder.hh"

#include <map>
#include <stdexcept>
#include <string>

namespace flecsi_lite::data {

ghost_plan build_ghost_plan(const std::vector<int>& ghost_owner, const std::vector<std::uint64_t>& ghost_id,
                            const std::function<std::size_t(std::uint64_t)>& owned_index_of, MPI_Comm comm) {
  int size = 1;
  MPI_Comm_size(comm, &size);
  if (ghost_owner.size() != ghost_id.size())
    throw std::invalid_argument("build_ghost_plan: ghost_owner and ghost_id differ in length");

  // What this rank receives: one contiguous block of ghost slots per owner.
  std::map<int, ghost_plan::peer> peers;
  std::vector<int> request_counts(size, 0);
  for (std::size_t k = 0; k < ghost_owner.size(); ++k) {
    const int owner = ghost_owner[k];
    auto [it, inserted] = peers.try_emplace(owner);
    if (inserted) {
      it->second.rank = owner;
      it->second.receive_first = k;
    } else if (it->second.receive_first + it->second.receive_count != k) {
      throw std::invalid_argument("build_ghost_plan: ghost slots of rank " + std::to_string(owner) +
                                  " are not contiguous");
    }
    ++it->second.receive_count;
    ++request_counts[owner];
  }

  // Tell every owner which ids we need, in our slot order.
  std::vector<int> incoming_counts(size);
  MPI_Alltoall(request_counts.data(), 1, MPI_INT, incoming_counts.data(), 1, MPI_INT, comm);
  std::vector<int> send_offsets(size, 0), receive_offsets(size, 0);
  for (int r = 1; r < size; ++r) {
    send_offsets[r] = send_offsets[r - 1] + request_counts[r - 1];
    receive_offsets[r] = receive_offsets[r - 1] + incoming_counts[r - 1];
  }
  std::vector<std::uint64_t> requests(ghost_id.size());
  {
    std::vector<int> fill = send_offsets;
    for (std::size_t k = 0; k < ghost_id.size(); ++k) requests[fill[ghost_owner[k]]++] = ghost_id[k];
  }
  std::vector<std::uint64_t> incoming(receive_offsets[size - 1] + incoming_counts[size - 1]);
  MPI_Alltoallv(requests.data(), request_counts.data(), send_offsets.data(), MPI_UINT64_T, incoming.data(),
                incoming_counts.data(), receive_offsets.data(), MPI_UINT64_T, comm);

  for (int r = 0; r < size; ++r) {
    if (incoming_counts[r] == 0) continue;
    auto& peer = peers[r];
    peer.rank = r;
    for (int i = 0; i < incoming_counts[r]; ++i) peer.send.push_back(owned_index_of(incoming[receive_offsets[r] + i]));
  }
  ghost_plan plan;
  for (auto& [rank, peer] : peers) plan.peers.push_back(std::move(peer));
  return plan;
}

}  // namespace flecsi_lite::data
