// The ntree topology (particles in 1, 2 and 3 dimensions), its public face: the distributed
// ntree<D> (sample-sort distribution, branch sharing, ghosts), space-filling-curve keys, the local
// hashed tree with its multipoles, its searches (group walk, radius search, Barnes-Hut) and the
// gravity walk, with its distributed tree (gravity_tree: locally essential trees).
// Internals live in ntree/detail/ and ntree/distributed/; the brute-force and cell-list
// references that tests and benchmarks compare the tree with, in ntree/reference/.
#pragma once
#include "flecsi_lite/topology/ntree/gravity/barnes_hut.hh"
#include "flecsi_lite/topology/ntree/gravity/gravity.hh"
#include "flecsi_lite/topology/ntree/gravity/gravity_tree.hh"
#include "flecsi_lite/topology/ntree/ntree.hh"
#include "flecsi_lite/topology/ntree/periodic.hh"
#include "flecsi_lite/topology/ntree/search/group_walk.hh"
#include "flecsi_lite/topology/ntree/search/neighbour_lists.hh"
#include "flecsi_lite/topology/ntree/search/radius_search.hh"
#include "flecsi_lite/topology/ntree/sfc/hilbert.hh"
#include "flecsi_lite/topology/ntree/sfc/keys.hh"
#include "flecsi_lite/topology/ntree/sfc/morton.hh"
#include "flecsi_lite/topology/ntree/sfc/ordering.hh"
#include "flecsi_lite/topology/ntree/space.hh"
#include "flecsi_lite/topology/ntree/tree/hashed_tree.hh"
#include "flecsi_lite/topology/ntree/tree/multipole.hh"
