// The communication plan of a distributed index space, from the point of view of one rank.
// SHARED entities are owned here and needed by other ranks (sent); GHOST entities are owned by
// other ranks and copied here (received into the ghost region, one contiguous block per peer).
// EXCLUSIVE entities are owned here and needed nowhere else.
#pragma once

#include <cstddef>
#include <vector>

namespace flecsi_lite::data {

struct ghost_plan {
  struct peer {
    int rank = 0;
    std::vector<std::size_t> send;  // owned indices whose values this peer needs, in its order
    std::size_t receive_first = 0;  // first ghost slot (counted from the start of the ghost region)
    std::size_t receive_count = 0;  // number of ghost slots this peer fills
  };
  std::vector<peer> peers;  // sorted by rank

  bool empty() const { return peers.empty(); }
};

}  // namespace flecsi_lite::data
