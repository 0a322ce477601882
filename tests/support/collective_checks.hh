// Helpers for the MPI I/O tests: file names private to one rank count, rank-0 file operations
// followed by a barrier, and the check that every rank saw the same error.
#pragma once

#include "flecsi_lite/runtime/context.hh"

#include <mpi.h>

#include <exception>
#include <filesystem>
#include <string>
#include <vector>

namespace io_test {

inline MPI_Comm comm() { return flecsi_lite::runtime::communicator(); }
inline int rank() { return flecsi_lite::runtime::rank(); }
inline int size() { return flecsi_lite::runtime::size(); }
inline void barrier() { MPI_Barrier(comm()); }

/// A file name unique to this test and rank count (the 1-, 2- and 4-rank runs may run at once).
inline std::string file_name(const std::string& stem, const std::string& extension = ".h5part") {
  return "mpi_io_" + stem + "_" + std::to_string(size()) + "ranks" + extension;
}

/// Rank 0 removes the files (and their partial files); every rank returns after that.
inline void remove_files(const std::vector<std::string>& paths) {
  if (rank() == 0)
    for (const auto& path : paths) {
      std::filesystem::remove(path);
      std::filesystem::remove(path + ".partial");
    }
  barrier();
}

/// Every rank's string, in rank order, on every rank.
inline std::vector<std::string> all_gather(const std::string& mine) {
  const int length = static_cast<int>(mine.size());
  std::vector<int> lengths(size()), offsets(size());
  MPI_Allgather(&length, 1, MPI_INT, lengths.data(), 1, MPI_INT, comm());
  int total = 0;
  for (int r = 0; r < size(); ++r) offsets[r] = total, total += lengths[r];
  std::string joined(total, '\0');
  MPI_Allgatherv(mine.data(), length, MPI_CHAR, joined.data(), lengths.data(), offsets.data(), MPI_CHAR, comm());
  std::vector<std::string> result;
  for (int r = 0; r < size(); ++r) result.push_back(joined.substr(offsets[r], lengths[r]));
  return result;
}

inline bool same_on_every_rank(const std::string& mine) {
  for (const auto& other : all_gather(mine))
    if (other != mine) return false;
  return true;
}

/// Runs `body` and returns the message of the Exception it throws, or a text saying that it
/// threw something else or nothing (which then fails the caller's Contains check).
template<class Exception, class Body>
std::string error_message(Body&& body) {
  try {
    body();
  } catch (const Exception& e) {
    return e.what();
  } catch (const std::exception& e) {
    return std::string("<wrong exception type> ") + e.what();
  }
  return "<no exception>";
}

}  // namespace io_test
