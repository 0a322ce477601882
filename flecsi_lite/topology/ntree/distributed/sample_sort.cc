// Regular sampling, splitter choice on rank 0 and the cut of the sorted particles into
// destination ranges (Shi & Schaeffer 1992, "Parallel sorting by regular sampling").
#include "flecsi_lite/topology/ntree/distributed/sample_sort.hh"

#include "flecsi_lite/runtime/context.hh"

#include <algorithm>
#include <stdexcept>

namespace flecsi_lite::topology::ntree {

std::vector<sample_entry> regular_sample(const key_id* sorted, const double* weights, std::size_t n,
                                         std::size_t max_samples) {
  std::vector<sample_entry> samples;
  if (n == 0) return samples;
  const std::size_t count = std::min(n, std::max<std::size_t>(max_samples, 1));
  samples.resize(count);
  for (std::size_t j = 0; j < count; ++j) {
    const std::size_t begin = j * n / count, end = (j + 1) * n / count;
    double weight = static_cast<double>(end - begin);
    if (weights) {
      weight = 0;
      for (std::size_t i = begin; i < end; ++i) weight += weights[i];
    }
    samples[j] = sample_entry{sorted[begin], weight};
  }
  return samples;
}

std::vector<splitter> choose_splitters(std::vector<sample_entry> samples, int parts) {
  if (parts < 1) throw std::invalid_argument("choose_splitters: parts must be at least 1");
  std::sort(samples.begin(), samples.end(),
            [](const sample_entry& a, const sample_entry& b) { return a.first < b.first; });
  const std::size_t m = samples.size();
  // before[i]: weight of the samples ahead of boundary i (boundary m is after the last one).
  std::vector<double> before(m + 1, 0.0);
  for (std::size_t i = 0; i < m; ++i) before[i + 1] = before[i] + samples[i].weight;
  if (!(before[m] > 0))  // all weights zero: fall back to balancing the sample count
    for (std::size_t i = 0; i < m; ++i) before[i + 1] = static_cast<double>(i + 1);
  const double total = before[m];

  std::vector<splitter> result(static_cast<std::size_t>(parts - 1));
  std::size_t previous = 0;
  for (int k = 1; k < parts; ++k) {
    const double target = total * k / parts;
    std::size_t i = static_cast<std::size_t>(std::lower_bound(before.begin(), before.end(), target) - before.begin());
    if (i > m) i = m;
    if (i > 0 && target - before[i - 1] < before[i] - target) --i;  // the nearer boundary
    i = std::max(i, previous);
    previous = i;
    splitter& s = result[static_cast<std::size_t>(k - 1)];
    if (i == m)
      s.after_all = 1;
    else
      s.first = samples[i].first;
  }
  return result;
}

std::vector<splitter> find_splitters(const key_id* sorted, const double* weights, std::size_t n,
                                     std::size_t sample_bytes, MPI_Comm comm) {
  int rank = 0, size = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  const std::vector<sample_entry> mine = regular_sample(sorted, weights, n, sample_bytes / sizeof(key_type));

  const int my_bytes = static_cast<int>(mine.size() * sizeof(sample_entry));
  std::vector<int> bytes(rank == 0 ? size : 0), offsets(rank == 0 ? size : 0);
  runtime::check_mpi(MPI_Gather(&my_bytes, 1, MPI_INT, bytes.data(), 1, MPI_INT, 0, comm),
                     "ntree sample sort: gather sample sizes");
  std::vector<sample_entry> all;
  if (rank == 0) {
    std::size_t total = 0;
    for (int r = 0; r < size; ++r) {
      offsets[r] = static_cast<int>(total);
      total += static_cast<std::size_t>(bytes[r]);
    }
    all.resize(total / sizeof(sample_entry));
  }
  runtime::check_mpi(
    MPI_Gatherv(mine.data(), my_bytes, MPI_BYTE, all.data(), bytes.data(), offsets.data(), MPI_BYTE, 0, comm),
    "ntree sample sort: gather samples");

  std::vector<splitter> splitters(static_cast<std::size_t>(size - 1));
  if (rank == 0) splitters = choose_splitters(std::move(all), size);
  runtime::check_mpi(
    MPI_Bcast(splitters.data(), static_cast<int>(splitters.size() * sizeof(splitter)), MPI_BYTE, 0, comm),
    "ntree sample sort: broadcast splitters");
  return splitters;
}

std::vector<std::size_t> split_sorted(const key_id* sorted, std::size_t n, const std::vector<splitter>& splitters) {
  std::vector<std::size_t> bounds(splitters.size() + 2, 0);
  for (std::size_t r = 0; r < splitters.size(); ++r) {
    const splitter& s = splitters[r];
    const std::size_t cut =
      s.after_all ? n : static_cast<std::size_t>(std::lower_bound(sorted, sorted + n, s.first) - sorted);
    bounds[r + 1] = std::max(cut, bounds[r]);
  }
  bounds.back() = n;
  return bounds;
}

}  // namespace flecsi_lite::topology::ntree
