// The ntree topology (particles in 1, 2 and 3 dimensions): keys, the local hashed tree and its
// searches, and the distributed ntree<D> with sample-sort distribution, branch sharing and ghosts.
#pragma once
#include "flecsi_lite/topology/ntree/barnes_hut.hh"
#include "flecsi_lite/topology/ntree/brute_force.hh"
#include "flecsi_lite/topology/ntree/cell_list.hh"
#include "flecsi_lite/topology/ntree/group_walk.hh"
#include "flecsi_lite/topology/ntree/hashed_tree.hh"
#include "flecsi_lite/topology/ntree/hilbert.hh"
#include "flecsi_lite/topology/ntree/keys.hh"
#include "flecsi_lite/topology/ntree/morton.hh"
#include "flecsi_lite/topology/ntree/multipole.hh"
#include "flecsi_lite/topology/ntree/neighbour_lists.hh"
#include "flecsi_lite/topology/ntree/ntree.hh"
#include "flecsi_lite/topology/ntree/ordering.hh"
#include "flecsi_lite/topology/ntree/periodic.hh"
#include "flecsi_lite/topology/ntree/radius_search.hh"
#include "flecsi_lite/topology/ntree/space.hh"
