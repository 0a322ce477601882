// Merge of runs of particles already in (key, id) order into one permutation (pairwise merging,
// as in the merge phase of a bottom-up merge sort; Knuth, TAOCP vol. 3, sec. 5.2.4): after the
// all-to-all each source rank's block is sorted, and so are owned and ghost blocks.
#pragma once

#include "flecsi_lite/topology/ntree/sfc/keys.hh"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <numeric>
#include <vector>

namespace flecsi_lite::topology::ntree {

/// Fills `permutation` (size n) so that particle permutation[i] is the i-th in (key, id) order,
/// given that the runs [starts[j], starts[j + 1]) (the last up to n) are each in that order.
/// O(n log(number of runs)).
inline void merge_sorted_runs(const key_type* keys, const std::uint64_t* ids, std::size_t n,
                              std::vector<std::size_t> starts, std::vector<std::size_t>& permutation) {
  permutation.resize(n);
  std::iota(permutation.begin(), permutation.end(), std::size_t{0});
  if (starts.empty() || starts.front() != 0) starts.insert(starts.begin(), 0);
  starts.push_back(n);
  const auto before = [keys, ids](std::size_t a, std::size_t b) {
    return keys[a] < keys[b] || (keys[a] == keys[b] && ids[a] < ids[b]);
  };
  std::vector<std::size_t> merged(n);
  while (starts.size() > 2) {
    std::vector<std::size_t> next{0};
    for (std::size_t j = 0; j + 1 < starts.size(); j += 2) {
      const std::size_t middle = starts[j + 1];
      const std::size_t end = j + 2 < starts.size() ? starts[j + 2] : middle;
      std::merge(permutation.begin() + starts[j], permutation.begin() + middle, permutation.begin() + middle,
                 permutation.begin() + end, merged.begin() + starts[j], before);
      next.push_back(end);
    }
    permutation.swap(merged);
    starts.swap(next);
  }
}

}  // namespace flecsi_lite::topology::ntree
