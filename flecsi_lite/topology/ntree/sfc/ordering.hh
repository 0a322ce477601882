// The total order of particles by (key, id): the permutation that sorts them, by an LSD radix
// sort of the keys (Knuth, TAOCP vol. 3, sec. 5.2.5) with ties between equal keys broken by id.
#pragma once

#include "flecsi_lite/execution/forall.hh"
#include "flecsi_lite/topology/ntree/sfc/keys.hh"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace flecsi_lite::topology::ntree {

/// Fills `permutation` (resized to n) so that input particle permutation[i] is the i-th in
/// increasing (key, id) order. With unique ids the order is total, so the sorted sequence does
/// not depend on the input order. Equal (key, id) pairs, which unique ids exclude, keep their
/// input order.
void sort_permutation(const key_type* keys, const std::uint64_t* ids, std::size_t n,
                      std::vector<std::size_t>& permutation);

/// As above, returning a new vector.
std::vector<std::size_t> sort_permutation(const key_type* keys, const std::uint64_t* ids, std::size_t n);

/// True when (keys[i], ids[i]) increase strictly with i.
bool is_sorted(const key_type* keys, const std::uint64_t* ids, std::size_t n);

/// out[i] = in[permutation[i]] for every i (gathers a field into sorted order). `in` and `out`
/// must not overlap.
template<class T>
void apply_permutation(const std::vector<std::size_t>& permutation, const T* in, T* out) {
  const std::size_t* source = permutation.data();
  flecsi_lite::forall(
    permutation.size(), [=](std::size_t i) { out[i] = in[source[i]]; }, "ntree::apply_permutation");
}

}  // namespace flecsi_lite::topology::ntree
