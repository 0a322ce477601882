// Radix sort of (key, id) pairs into a permutation: six stable counting-sort passes of 11 bits
// over the keys (passes where all keys share the digit are skipped), then ties sorted by id.
#include "flecsi_lite/topology/ntree/sfc/ordering.hh"

#include <algorithm>
#include <array>
#include <numeric>

namespace flecsi_lite::topology::ntree {
namespace {

constexpr int digit_bits = 11;
constexpr int pass_count = (64 + digit_bits - 1) / digit_bits;
constexpr std::size_t bucket_count = std::size_t{1} << digit_bits;
// Below this size a comparison sort is faster than building histograms.
constexpr std::size_t small_size = 256;

inline std::size_t digit(key_type key, int pass) {
  return static_cast<std::size_t>(key >> (pass * digit_bits)) & (bucket_count - 1);
}

// Stable LSD radix sort of `keys` carrying `order`; both are sorted in place.
void radix_sort(std::vector<key_type>& keys, std::vector<std::size_t>& order) {
  const std::size_t n = keys.size();
  std::vector<std::array<std::size_t, bucket_count>> histograms(pass_count);
  for (auto& histogram : histograms) histogram.fill(0);
  for (const key_type key : keys)
    for (int pass = 0; pass < pass_count; ++pass) ++histograms[pass][digit(key, pass)];

  std::vector<key_type> keys_out(n);
  std::vector<std::size_t> order_out(n);
  for (int pass = 0; pass < pass_count; ++pass) {
    auto& offsets = histograms[pass];
    if (offsets[digit(keys[0], pass)] == n) continue;  // every key has this digit
    std::size_t running = 0;
    for (auto& offset : offsets) {
      const std::size_t count = offset;
      offset = running;
      running += count;
    }
    for (std::size_t i = 0; i < n; ++i) {
      const std::size_t target = offsets[digit(keys[i], pass)]++;
      keys_out[target] = keys[i];
      order_out[target] = order[i];
    }
    keys.swap(keys_out);
    order.swap(order_out);
  }
}

}  // namespace

void sort_permutation(const key_type* keys, const std::uint64_t* ids, std::size_t n,
                      std::vector<std::size_t>& permutation) {
  permutation.resize(n);
  std::iota(permutation.begin(), permutation.end(), std::size_t{0});
  if (n == 0) return;

  const auto by_id = [ids](std::size_t a, std::size_t b) { return ids[a] < ids[b] || (ids[a] == ids[b] && a < b); };
  if (n < small_size) {
    std::sort(permutation.begin(), permutation.end(),
              [&](std::size_t a, std::size_t b) { return keys[a] < keys[b] || (keys[a] == keys[b] && by_id(a, b)); });
    return;
  }

  std::vector<key_type> sorted_keys(keys, keys + n);
  radix_sort(sorted_keys, permutation);
  // Runs of equal keys (coincident particles, rare) are put in id order.
  for (std::size_t begin = 0; begin < n;) {
    std::size_t end = begin + 1;
    while (end < n && sorted_keys[end] == sorted_keys[begin]) ++end;
    if (end - begin > 1) std::sort(permutation.begin() + begin, permutation.begin() + end, by_id);
    begin = end;
  }
}

std::vector<std::size_t> sort_permutation(const key_type* keys, const std::uint64_t* ids, std::size_t n) {
  std::vector<std::size_t> permutation;
  sort_permutation(keys, ids, n, permutation);
  return permutation;
}

bool is_sorted(const key_type* keys, const std::uint64_t* ids, std::size_t n) {
  for (std::size_t i = 1; i < n; ++i) {
    if (keys[i - 1] > keys[i]) return false;
    if (keys[i - 1] == keys[i] && ids[i - 1] >= ids[i]) return false;
  }
  return true;
}

}  // namespace flecsi_lite::topology::ntree
