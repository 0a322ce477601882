// group_walk<D> compiled once per dimension (group_walk.hh declares it extern): the neighbour
// search is the same code in every program, so it is generated here, not in each translation unit.
#include "flecsi_lite/topology/ntree/search/group_walk.hh"

namespace flecsi_lite::topology::ntree {
template class group_walk<1>;
template class group_walk<2>;
template class group_walk<3>;
}  // namespace flecsi_lite::topology::ntree
