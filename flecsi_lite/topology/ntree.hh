// The ntree topology (particles in 1, 2 and 3 dimensions), its public face: the distributed
// ntree<D> (sample-sort distribution, branch sharing, ghosts), space-filling-curve keys, the local
// hashed tree with its multipoles, its searches (group walk, radius search, Barnes-Hut) and the
// gravity walk, with its distributed tree (gravity_tree: locally essential trees).
// Folders by concern: sfc/ (keys), tree/ (the local hashed tree and its multipoles), search/
// (neighbour searches), gravity/ (the gravity walk, the distributed gravity tree, direct
// summation), distributed/ (sample sort, particle exchange, branch sharing, ghosts), reference/
// (brute force and cell list, what tests and benchmarks compare the tree with). Internals live
// in the detail/ folders, each included only from the folder that holds it (tests/layout).
#pragma once
#include "flecsi_lite/topology/ntree/gravity/barnes_hut.hh"
#include "flecsi_lite/topology/ntree/gravity/direct_gravity.hh"
#include "flecsi_lite/topology/ntree/gravity/gravity.hh"
#include "flecsi_lite/topology/ntree/gravity/gravity_tree.hh"
#include "flecsi_lite/topology/ntree/ntree.hh"
#include "flecsi_lite/topology/ntree/periodic.hh"
#include "flecsi_lite/topology/ntree/reference/brute_force.hh"
#include "flecsi_lite/topology/ntree/reference/cell_list.hh"
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
