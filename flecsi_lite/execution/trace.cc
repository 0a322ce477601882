#include "flecsi_lite/execution/trace.hh"

#include "flecsi_lite/runtime/context.hh"

#include <iomanip>
#include <ostream>
#include <sstream>

namespace flecsi_lite::execution {

void write_chrome_trace(const std::vector<trace_event>& events, std::ostream& out) {
  // Each rank formats its events; rank 0 gathers the text and writes one JSON array, one
  // "process" per rank, times in microseconds.
  std::ostringstream mine;
  mine << std::fixed << std::setprecision(3);
  const int rank = runtime::rank();
  for (const auto& e : events) {
    std::string name;
    for (char c : e.name) name += (c == '"' || c == '\\') ? '_' : c;
    mine << "{\"name\":\"" << name << "\",\"cat\":\"" << e.kind << "\",\"ph\":\"X\",\"pid\":" << rank
         << ",\"tid\":0,\"ts\":" << e.begin * 1e6 << ",\"dur\":" << (e.end - e.begin) * 1e6
         << ",\"args\":{\"sequence\":" << e.sequence << "}},\n";
  }
  const std::string text = mine.str();
  int length = static_cast<int>(text.size());
  const int size = runtime::size();
  std::vector<int> lengths(size), offsets(size, 0);
  MPI_Gather(&length, 1, MPI_INT, lengths.data(), 1, MPI_INT, 0, runtime::communicator());
  std::string all;
  if (rank == 0) {
    for (int r = 1; r < size; ++r) offsets[r] = offsets[r - 1] + lengths[r - 1];
    all.resize(offsets[size - 1] + lengths[size - 1]);
  }
  MPI_Gatherv(text.data(), length, MPI_CHAR, all.data(), lengths.data(), offsets.data(), MPI_CHAR, 0,
              runtime::communicator());
  if (rank != 0) return;
  if (all.size() >= 2) all.resize(all.size() - 2);  // the last ",\n"
  out << "[\n" << all << "\n]\n";
}

} // namespace flecsi_lite::execution
