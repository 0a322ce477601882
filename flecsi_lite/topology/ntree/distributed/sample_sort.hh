// Splitters of the parallel sample sort that distributes particles by (key, id): every rank sends
// a regular sample of its sorted keys to rank 0, which cuts the sample's accumulated weight
// (particle count or work) into equal parts (Shi & Schaeffer 1992; FleCSPH, seed sec. 2.3.3).
#pragma once

#include "flecsi_lite/topology/ntree/sfc/keys.hh"

#include <mpi.h>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace flecsi_lite::topology::ntree {

/// The total order of particles: by key, ties by the unique id.
struct key_id {
  key_type key = 0;
  std::uint64_t id = 0;

  friend bool operator<(const key_id& a, const key_id& b) { return a.key < b.key || (a.key == b.key && a.id < b.id); }
  friend bool operator==(const key_id& a, const key_id& b) { return a.key == b.key && a.id == b.id; }
};

/// Rank r receives the particles p with splitter[r - 1] <= p < splitter[r] (splitter[-1] is
/// below every particle, splitter[size - 1] above). A splitter marked `after_all` is above
/// every particle: the ranks from there on receive none.
struct splitter {
  key_id first;                 ///< the smallest (key, id) the next rank receives
  std::uint64_t after_all = 0;  ///< 1: no particle reaches the next rank
};

/// One entry of a rank's sample: a particle and the weight of the run of sorted particles it
/// stands for (from it up to the next sample of the same rank).
struct sample_entry {
  key_id first;
  double weight = 0;
};

/// Regular sample of n particles already in (key, id) order (sorted[i] is the i-th): at most
/// `max_samples` entries at evenly spaced positions; entry j weighs the sum of `weights` over its
/// run (or the run's length when `weights` is null). With n <= max_samples every particle is a
/// sample and the splitters come out exact.
std::vector<sample_entry> regular_sample(const key_id* sorted, const double* weights, std::size_t n,
                                         std::size_t max_samples);

/// Rank 0's choice: `parts - 1` splitters cutting the merged samples (sorted by (key, id)) into
/// parts of nearly equal accumulated weight; each cut is placed at the sample boundary nearest
/// to its target weight k * total / parts. Pure function (no MPI), for tests.
std::vector<splitter> choose_splitters(std::vector<sample_entry> samples, int parts);

/// Collective over `comm`: gathers every rank's regular sample (`sample_bytes` of keys per rank,
/// as in the seed: sample_bytes / 8 samples) on rank 0, chooses the splitters there and
/// broadcasts them. `sorted` and `weights` describe this rank's particles in (key, id) order.
std::vector<splitter> find_splitters(const key_id* sorted, const double* weights, std::size_t n,
                                     std::size_t sample_bytes, MPI_Comm comm);

/// Destination ranges: particles [bounds[r], bounds[r + 1]) of the sorted sequence go to rank r
/// (size() + 1 entries, bounds[0] = 0, bounds.back() = n).
std::vector<std::size_t> split_sorted(const key_id* sorted, std::size_t n, const std::vector<splitter>& splitters);

}  // namespace flecsi_lite::topology::ntree
