// Sender-driven ghost plans of the ntree topology (the executor copies values along them).
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
}  // namespace

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

}  // namespace flecsi_lite::topology::ntree
