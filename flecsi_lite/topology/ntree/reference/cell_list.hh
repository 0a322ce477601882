// A uniform cell list (linked-cell method; Hockney & Eastwood 1988, sec. 8-4), the baseline the
// tree searches are benchmarked against: particles binned into cells no smaller than the
// largest interaction radius, each target scanning its own and the adjacent 3^D - 1 cells.
#pragma once

#include "flecsi_lite/topology/ntree/search/neighbour_lists.hh"
#include "flecsi_lite/topology/ntree/space.hh"

#include <algorithm>
#include <array>
#include <cassert>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace flecsi_lite::topology::ntree {

/// Non-periodic only. Neighbours of a target are visited cell by cell (ascending index inside a
/// cell), not in globally ascending order: enough for sums that need no canonical order.
template<int D>
class cell_list {
 public:
  /// Bins the n particles at x into cells of side at least `cell_size`, which must be at least
  /// the largest interaction radius of the searches to come. The side grows if the grid would
  /// have more than 8 cells per particle.
  void build(const point<D>* x, const double* h, std::size_t n, double cell_size) {
    assert(cell_size > 0);
    x_ = x;
    h_ = h;
    n_ = n;
    bounds_ = box<D>::empty();
    for (std::size_t i = 0; i < n; ++i) bounds_.extend(x[i]);
    if (n == 0) return;
    // A margin far above rounding: a pair closer than the requested size can never be cut
    // two cells apart by the rounding of the cell index.
    cell_size *= 1 + 1e-9;
    const double max_cells = 8.0 * static_cast<double>(n) + 1;
    for (;;) {
      double cells = 1;
      for (int k = 0; k < D; ++k) {
        dims_[k] = static_cast<std::size_t>((bounds_.hi[k] - bounds_.lo[k]) / cell_size) + 1;
        cells *= static_cast<double>(dims_[k]);
      }
      if (cells <= max_cells) break;
      cell_size *= 2;
    }
    cell_size_ = cell_size;
    std::size_t cell_total = 1;
    for (int k = 0; k < D; ++k) cell_total *= dims_[k];
    cell_start_.assign(cell_total + 1, 0);
    cell_of_.resize(n);
    for (std::size_t i = 0; i < n; ++i) {
      cell_of_[i] = linear(coordinates(x[i]));
      ++cell_start_[cell_of_[i] + 1];
    }
    for (std::size_t c = 0; c < cell_total; ++c) cell_start_[c + 1] += cell_start_[c];
    members_.resize(n);
    std::vector<std::size_t> fill(cell_start_.begin(), cell_start_.end() - 1);
    for (std::size_t i = 0; i < n; ++i) members_[fill[cell_of_[i]]++] = static_cast<std::uint32_t>(i);
  }

  double cell_size() const { return cell_size_; }

  /// Calls apply(a, b) for every neighbour b of target a (criterion of neighbour_lists.hh).
  template<class F>
  void for_each_neighbour(std::size_t a, const search_options& options, F&& apply) const {
    const std::array<std::size_t, D> home = coordinates(x_[a]);
    std::array<std::size_t, D> lo, hi;
    for (int k = 0; k < D; ++k) {
      lo[k] = home[k] > 0 ? home[k] - 1 : 0;
      hi[k] = std::min(home[k] + 1, dims_[k] - 1);
    }
    std::array<std::size_t, D> c = lo;
    for (;;) {
      const std::size_t cell = linear(c);
      for (std::size_t j = cell_start_[cell]; j < cell_start_[cell + 1]; ++j) {
        const std::uint32_t b = members_[j];
        const double radius = interaction_radius(options.kind, options.support, h_[a], h_[b]);
        if (within_radius(distance_squared<D>(x_[a], x_[b]), radius)) apply(a, std::size_t{b});
      }
      int k = 0;
      while (k < D && c[k] == hi[k]) {
        c[k] = lo[k];
        ++k;
      }
      if (k == D) break;
      ++c[k];
    }
  }

  std::size_t bytes() const {
    return cell_start_.size() * sizeof(std::size_t) + members_.size() * sizeof(std::uint32_t) +
           cell_of_.size() * sizeof(std::size_t);
  }

 private:
  std::array<std::size_t, D> coordinates(const point<D>& x) const {
    std::array<std::size_t, D> c;
    for (int k = 0; k < D; ++k) {
      const double u = (x[k] - bounds_.lo[k]) / cell_size_;
      c[k] = std::min(static_cast<std::size_t>(std::max(u, 0.0)), dims_[k] - 1);
    }
    return c;
  }

  std::size_t linear(const std::array<std::size_t, D>& c) const {
    std::size_t index = 0;
    for (int k = D - 1; k >= 0; --k) index = index * dims_[k] + c[k];
    return index;
  }

  const point<D>* x_ = nullptr;
  const double* h_ = nullptr;
  std::size_t n_ = 0;
  box<D> bounds_ = box<D>::empty();
  double cell_size_ = 1;
  std::array<std::size_t, D> dims_{};
  std::vector<std::size_t> cell_start_;
  std::vector<std::size_t> cell_of_;
  std::vector<std::uint32_t> members_;
};

}  // namespace flecsi_lite::topology::ntree
