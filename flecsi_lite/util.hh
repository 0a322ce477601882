// Small things with no better home: exact (order-independent) summation, did-you-mean lookup of
// misspelled names, and the Kokkos spaces fields live in.
#pragma once
#include "flecsi_lite/util/edit_distance.hh"
#include "flecsi_lite/util/exact_sum.hh"
#include "flecsi_lite/util/kokkos.hh"
