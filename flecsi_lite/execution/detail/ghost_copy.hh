// Internals of the executor: the start of one ghost copy of several fields of a topology, one
// message per peer (all fields packed together, each as the values that changed since its last
// copy to that peer, unpacked per field when the messages arrive),
// and of one ghost reduction (the copy's messages in reverse: each peer's ghost block goes back
// to its owner, which combines it into the owned values).
#pragma once

#include "flecsi_lite/data/field_storage.hh"
#include "flecsi_lite/data/topology_base.hh"
#include "flecsi_lite/execution/executor.hh"
#include "flecsi_lite/execution/launch.hh"

#include <functional>
#include <memory>
#include <ostream>
#include <vector>

namespace flecsi_lite::execution::detail {

/// What a field's ghost copies last sent to each peer (packed in the plan's send order), so
/// that the next copy sends only the values that changed; made anew at every layout change.
struct sent_ghost_values {
  std::vector<std::vector<std::byte>> per_peer;  // by the plan's peer index
};

/// A field of a copy: its storage, what its copies sent, and whether the peers' ghosts still
/// hold that (decided when the copy was recorded: no launch wrote the ghosts since the last copy).
struct copied_field {
  data::field_storage_base* storage;
  std::shared_ptr<sent_ghost_values> sent;
  bool receivers_hold_sent;
};

/// The launch's start: packs and posts, counting messages and bytes in `traffic`; sets the
/// launch's finish (unpack).
std::function<void(launch&)> ghost_copy_start(data::topology_base* topology, std::vector<copied_field> fields, int tag,
                                              ghost_traffic* traffic);

/// The start of a ghost reduction of `storage`: sends each peer the ghost block it fills and
/// posts the receive of the ghosts it holds of this rank's entities. Sets the launch's finish:
/// combine, peer by peer in rank order (the periodic images of the rank's own entities in their
/// place).
std::function<void(launch&)> ghost_reduction_start(data::topology_base* topology, data::field_storage_base* storage,
                                                   combine_into_owned combine, int tag, ghost_traffic* traffic);

/// Collective: the ghost traffic per rank (min / mean / max over ranks of messages and bytes
/// sent), written on rank 0 before the timer table.
void report_ghost_traffic(const ghost_traffic& traffic, std::ostream& out);

}  // namespace flecsi_lite::execution::detail
