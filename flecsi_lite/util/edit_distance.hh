// Levenshtein distance and "did you mean" lookup, for helpful errors on misspelled names.
#pragma once

#include <algorithm>
#include <string>
#include <string_view>
#include <vector>

namespace flecsi_lite::util {

/// Number of single-character insertions, deletions and substitutions turning a into b.
inline std::size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<std::size_t> previous(b.size() + 1), current(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) previous[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    current[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t substitution = previous[j - 1] + (a[i - 1] == b[j - 1] ? 0 : 1);
      current[j] = std::min({previous[j] + 1, current[j - 1] + 1, substitution});
    }
    std::swap(previous, current);
  }
  return previous[b.size()];
}

/// Names longer than this get no suggestion: a typo of a name is about as long as the name, and
/// the cost of a distance is the product of the two lengths.
inline constexpr std::size_t longest_suggested_name = 256;

/// The candidate closest to `name`, or "" when none is within a plausible typo distance. The
/// distance is at least the difference of the lengths, so a candidate whose length differs by the
/// best distance so far or more is skipped without computing it.
template<class Range>
std::string nearest_name(std::string_view name, const Range& candidates) {
  std::string best;
  if (name.size() > longest_suggested_name) return best;
  std::size_t best_distance = std::max<std::size_t>(3, name.size() / 2) + 1;
  for (const auto& candidate : candidates) {
    const std::string_view other = candidate;
    const std::size_t length_difference =
      name.size() > other.size() ? name.size() - other.size() : other.size() - name.size();
    if (length_difference >= best_distance) continue;
    const std::size_t d = edit_distance(name, other);
    if (d < best_distance) {
      best_distance = d;
      best = candidate;
    }
  }
  return best;
}

}  // namespace flecsi_lite::util
