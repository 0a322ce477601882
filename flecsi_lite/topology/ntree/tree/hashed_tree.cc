// hashed_tree<D> compiled once per dimension (hashed_tree.hh declares it extern): every program
// builds the same local tree, so its code is generated here, not in each translation unit.
#include "flecsi_lite/topology/ntree/tree/hashed_tree.hh"

namespace flecsi_lite::topology::ntree {
template class hashed_tree<1>;
template class hashed_tree<2>;
template class hashed_tree<3>;
}  // namespace flecsi_lite::topology::ntree
