// Collective agreement on failures: when any rank fails, every rank throws the same io_error
// (kind and message of the lowest failing rank), so that no rank is left waiting in a collective.
#pragma once

#include "flecsi_lite/io/io_error.hh"

#include <mpi.h>

#include <exception>
#include <optional>
#include <string>
#include <string_view>

namespace flecsi_lite::io {

/// This rank's number in `comm`.
int rank_of(MPI_Comm comm);

/// A failure seen by one rank, before the ranks agree on it.
struct failure_record {
  failure kind = failure::system;
  std::string message;
};

/// Collective: throws on every rank the failure of the lowest rank whose `local` is set; returns
/// on every rank when no rank failed.
void raise_if_any(MPI_Comm comm, const std::optional<failure_record>& local);

/// Collective: runs `body` (which must make no collective call, since a rank that throws early
/// would skip it) and then agrees with the other ranks as raise_if_any does.
template<class Body>
void agree(MPI_Comm comm, Body&& body) {
  std::optional<failure_record> local;
  try {
    body();
  } catch (const io_error& e) {
    local = failure_record{e.kind(), e.what()};
  } catch (const std::exception& e) {
    local = failure_record{failure::system, e.what()};
  }
  raise_if_any(comm, local);
}

/// Collective: true when `bytes` are identical on every rank (compared by a 64-bit FNV-1a hash,
/// which is enough to catch ranks that pass different names or values by mistake).
bool same_on_all_ranks(MPI_Comm comm, std::string_view bytes);

}  // namespace flecsi_lite::io
