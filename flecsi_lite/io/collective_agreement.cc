// Collective agreement on failures and on values (see collective_agreement.hh).
#include "flecsi_lite/io/collective_agreement.hh"

#include <cstdint>

namespace flecsi_lite::io {

int rank_of(MPI_Comm comm) {
  int rank = 0;
  MPI_Comm_rank(comm, &rank);
  return rank;
}

void raise_if_any(MPI_Comm comm, const std::optional<failure_record>& local) {
  int rank = 0, size = 1;
  MPI_Comm_rank(comm, &rank);
  MPI_Comm_size(comm, &size);
  const int mine = local ? rank : size;
  int first = size;
  MPI_Allreduce(&mine, &first, 1, MPI_INT, MPI_MIN, comm);
  if (first == size) return;

  // The lowest failing rank tells the others what happened.
  unsigned long long header[2] = {0, 0};
  std::string message;
  if (rank == first) {
    header[0] = static_cast<unsigned long long>(local->kind);
    header[1] = local->message.size();
    message = local->message;
  }
  MPI_Bcast(header, 2, MPI_UNSIGNED_LONG_LONG, first, comm);
  message.resize(header[1]);
  if (header[1] > 0) MPI_Bcast(message.data(), static_cast<int>(header[1]), MPI_CHAR, first, comm);
  throw_io_error(static_cast<failure>(header[0]), message);
}

bool same_on_all_ranks(MPI_Comm comm, std::string_view bytes) {
  std::uint64_t hash = 14695981039346656037ull;  // FNV-1a offset basis
  for (unsigned char c : bytes) {
    hash ^= c;
    hash *= 1099511628211ull;  // FNV-1a prime
  }
  // max(~h) == ~min(h), so one MAX reduction gives both extremes; they meet iff all are equal.
  std::uint64_t values[2] = {hash, ~hash}, maxima[2] = {0, 0};
  MPI_Allreduce(values, maxima, 2, MPI_UINT64_T, MPI_MAX, comm);
  return maxima[0] == ~maxima[1];
}

}  // namespace flecsi_lite::io
