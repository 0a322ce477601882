// reduce_ghosts<op>(field): the ghost copy in reverse. A task that computes contributions to
// other ranks' entities writes them into its ghost slots (accessor<rw, wo> or <rw, rw>); then
//
//   execute<scatter_contributions>(f(p));            // writes owned values and ghost slots
//   reduce_ghosts<reduction::min>(f(p));             // owner(i) = min(owner(i), every ghost of i)
//   execute<use_totals>(f(p));                       // reads the combined owned values
//
// Each rank's ghost block of a peer travels back to that peer (one message per peer, the ghost
// copy's messages the other way) and is combined into the owned values there, peers in rank
// order (a sum is the same from run to run; min and max on any rank count). The owned values
// change, so their ghosts are stale afterwards. Needs ghost values some task defined since the
// last change of the owned values or of the layout (else a logic_error names the field).
#pragma once

#include "flecsi_lite/data/field.hh"
#include "flecsi_lite/execution/executor.hh"
#include "flecsi_lite/execution/future.hh"
#include "flecsi_lite/execution/reduction.hh"

#include <cstring>

namespace flecsi_lite {

/// Combines every ghost value of `ref` into its owner's value with Op (reduction::sum, min,
/// max); a future that is ready once the owned values are combined.
template<class Op, class T, class Topo>
future<void> reduce_ghosts(const field_reference<T, Topo>& ref) {
  if (!ref.present()) return {};  // an absent field: nothing to combine
  data::field_storage<T>* storage = &ref.storage();
  execution::combine_into_owned combine = [storage](const std::vector<std::size_t>& owned, const std::byte* values) {
    const auto view = storage->view();
    for (std::size_t i = 0; i < owned.size(); ++i) {
      T incoming;
      std::memcpy(&incoming, values + i * sizeof(T), sizeof(T));
      view(owned[i]) = Op::combine(view(owned[i]), incoming);
    }
  };
  return future<void>(execution::executor::instance().record_ghost_reduction(
    {ref.topology().instance_id(), &ref.topology(), ref.id(), storage, rw, ro}, std::move(combine)));
}

}  // namespace flecsi_lite
