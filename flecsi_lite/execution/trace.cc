// Chrome trace JSON of the executor's launches (trace.hh): per rank one process, tasks on the
// compute track (tid 0), communication in flight on tracks 1, 2, ... (a copy or collective on
// the first track free at its start, so no track holds overlapping events).
#include "flecsi_lite/execution/trace.hh"

#include "flecsi_lite/runtime/context.hh"

#include <algorithm>
#include <iomanip>
#include <ostream>
#include <sstream>

namespace flecsi_lite::execution {

std::vector<int> trace_tracks(const std::vector<trace_event>& events) {
  std::vector<std::size_t> order(events.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(),
                   [&](std::size_t a, std::size_t b) { return events[a].begin < events[b].begin; });
  std::vector<int> track(events.size(), 0);
  std::vector<double> busy_until;  // of communication tracks 1, 2, ...
  for (std::size_t i : order) {
    const auto& e = events[i];
    if (e.kind == "task" || (e.kind == "failed" && e.name.find("ghost copy") != 0)) continue;
    std::size_t t = 0;
    while (t < busy_until.size() && busy_until[t] > e.begin) ++t;
    if (t == busy_until.size()) busy_until.push_back(0);
    busy_until[t] = e.end;
    track[i] = static_cast<int>(t) + 1;
  }
  return track;
}

void write_chrome_trace(const std::vector<trace_event>& events, std::ostream& out) {
  // Each rank formats its events; rank 0 gathers the text and writes one JSON array, one
  // "process" per rank, times in microseconds.
  std::ostringstream mine;
  mine << std::fixed << std::setprecision(3);
  const int rank = runtime::rank();
  const std::vector<int> track = trace_tracks(events);
  const int tracks = events.empty() ? 1 : *std::max_element(track.begin(), track.end()) + 1;
  auto metadata = [&](const char* what, int tid, const std::string& name) {
    mine << "{\"name\":\"" << what << "\",\"ph\":\"M\",\"pid\":" << rank << ",\"tid\":" << tid
         << ",\"args\":{\"name\":\"" << name << "\"}},\n";
  };
  metadata("process_name", 0, "rank " + std::to_string(rank));
  mine << "{\"name\":\"process_sort_index\",\"ph\":\"M\",\"pid\":" << rank
       << ",\"tid\":0,\"args\":{\"sort_index\":" << rank << "}},\n";
  metadata("thread_name", 0, "compute");
  for (int t = 1; t < std::max(tracks, 2); ++t)
    metadata("thread_name", t, t == 1 ? std::string("communication") : "communication " + std::to_string(t));
  for (std::size_t i = 0; i < events.size(); ++i) {
    const auto& e = events[i];
    std::string name;
    for (char c : e.name) name += (c == '"' || c == '\\') ? '_' : c;
    mine << "{\"name\":\"" << name << "\",\"cat\":\"" << e.kind << "\",\"ph\":\"X\",\"pid\":" << rank
         << ",\"tid\":" << track[i] << ",\"ts\":" << e.begin * 1e6 << ",\"dur\":" << (e.end - e.begin) * 1e6
         << ",\"args\":{\"sequence\":" << e.sequence << ",\"dependencies\":[";
    for (std::size_t d = 0; d < e.dependencies.size(); ++d) mine << (d ? "," : "") << e.dependencies[d];
    mine << "]}},\n";
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

}  // namespace flecsi_lite::execution
