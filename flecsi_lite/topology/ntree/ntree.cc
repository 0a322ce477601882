// The members of ntree<D> compiled once per dimension here (ntree.hh declares them extern): the
// distribution pipeline is the same code in every program, so it is generated once, not in each
// translation unit that holds a topology.
#include "flecsi_lite/topology/ntree/ntree.hh"

namespace flecsi_lite::topology::ntree {
template class ntree<1>;
template class ntree<2>;
template class ntree<3>;
}  // namespace flecsi_lite::topology::ntree
