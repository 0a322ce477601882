// Reference neighbour search by direct comparison of every target with every source image
// (O(N^2)): the definition the tree searches must reproduce exactly, for tests and benchmarks.
#pragma once

#include "flecsi_lite/execution/forall.hh"
#include "flecsi_lite/topology/ntree/periodic.hh"
#include "flecsi_lite/topology/ntree/search/neighbour_lists.hh"
#include "flecsi_lite/topology/ntree/space.hh"

#include <cstddef>
#include <cstdint>

namespace flecsi_lite::topology::ntree {

/// Neighbour lists of n particles by the pair criterion of neighbour_lists.hh, trying every
/// allowed image shift of `space` for every pair; ascending (b, shift code) per target.
template<int D>
void brute_force_neighbours(const point<D>* x, const double* h, std::size_t n, const domain<D>& space,
                            const search_options& options, neighbour_lists& out) {
  const auto shifts = space.shift_table();
  const std::uint32_t allowed = space.allowed_shifts();
  const bool periodic = space.any_periodic();
  // visit(b, code) for every neighbour image of target a.
  const auto scan = [&](std::size_t a, auto&& visit) {
    for (std::size_t b = 0; b < n; ++b) {
      const double radius = interaction_radius(options.kind, options.support, h[a], h[b]);
      for (std::uint32_t rest = allowed; rest != 0; rest &= rest - 1) {
        const int code = __builtin_ctz(rest);
        point<D> image;
        for (int k = 0; k < D; ++k) image[k] = x[b][k] + shifts[code][k];
        if (within_radius(distance_squared<D>(x[a], image), radius)) visit(b, static_cast<shift_code>(code));
      }
    }
  };
  out.offsets.assign(n + 1, 0);
  out.runs.clear();
  out.in_runs = false;
  flecsi_lite::forall(
    n,
    [&](std::size_t a) {
      if (options.is_target(a)) scan(a, [&](std::size_t, shift_code) { ++out.offsets[a]; });
    },
    "ntree::brute_force::count");
  const std::size_t total = flecsi_lite::exclusive_scan(out.offsets.data(), n + 1, "ntree::brute_force::offsets");
  out.neighbours.resize(total);
  out.shifts.resize(periodic ? total : 0);
  flecsi_lite::forall(
    n,
    [&](std::size_t a) {
      if (!options.is_target(a)) return;
      std::size_t at = out.offsets[a];
      scan(a, [&](std::size_t b, shift_code code) {
        out.neighbours[at] = static_cast<std::uint32_t>(b);
        if (periodic) out.shifts[at] = code;
        ++at;
      });
    },
    "ntree::brute_force::fill");
}

}  // namespace flecsi_lite::topology::ntree
