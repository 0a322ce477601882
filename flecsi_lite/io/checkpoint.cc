// Checkpoint writing and reading on top of the H5Part writer and reader (see checkpoint.hh).
#include "flecsi_lite/io/checkpoint.hh"

#include <algorithm>
#include <limits>
#include <vector>

namespace flecsi_lite::io {

void write_checkpoint(const std::string& path, const step_info& info, const run_state& state,
                      const std::function<void(h5part_writer&)>& write_arrays, MPI_Comm comm) {
  h5part_writer writer(path, comm);
  writer.set_attribute(checkpoint_marker, std::int64_t{1});
  for (const auto& [name, value] : state) writer.set_attribute(checkpoint_state_prefix + name, value);
  writer.begin_step(info);
  write_arrays(writer);
  writer.end_step();
  writer.close();
}

checkpoint_contents read_checkpoint(const h5part_reader& reader) {
  const auto names = reader.root_attribute_names();
  if (std::find(names.begin(), names.end(), checkpoint_marker) == names.end() || !reader.has_step(0))
    throw file_error("'" + reader.path() + "' is not a checkpoint (no root attribute '" + checkpoint_marker +
                     "' or no Step#0)");
  checkpoint_contents contents;
  contents.info = reader.step_information(0);
  const std::string prefix = checkpoint_state_prefix;
  for (const auto& name : names)
    if (name.compare(0, prefix.size(), prefix) == 0)
      contents.state[name.substr(prefix.size())] = reader.root_attribute(name);
  return contents;
}

std::optional<std::uint64_t> duplicate_id(const std::uint64_t* ids, std::size_t count, MPI_Comm comm) {
  int size = 1;
  MPI_Comm_size(comm, &size);
  std::vector<int> send_counts(size, 0), receive_counts(size), send_offsets(size, 0), receive_offsets(size, 0);
  for (std::size_t i = 0; i < count; ++i) ++send_counts[ids[i] % static_cast<std::uint64_t>(size)];
  MPI_Alltoall(send_counts.data(), 1, MPI_INT, receive_counts.data(), 1, MPI_INT, comm);
  for (int r = 1; r < size; ++r) {
    send_offsets[r] = send_offsets[r - 1] + send_counts[r - 1];
    receive_offsets[r] = receive_offsets[r - 1] + receive_counts[r - 1];
  }
  std::vector<std::uint64_t> outgoing(count), incoming(receive_offsets[size - 1] + receive_counts[size - 1]);
  {
    std::vector<int> next = send_offsets;
    for (std::size_t i = 0; i < count; ++i) outgoing[next[ids[i] % static_cast<std::uint64_t>(size)]++] = ids[i];
  }
  MPI_Alltoallv(outgoing.data(), send_counts.data(), send_offsets.data(), MPI_UINT64_T, incoming.data(),
                receive_counts.data(), receive_offsets.data(), MPI_UINT64_T, comm);
  std::sort(incoming.begin(), incoming.end());
  std::uint64_t twice = std::numeric_limits<std::uint64_t>::max();
  const auto found = std::adjacent_find(incoming.begin(), incoming.end());
  if (found != incoming.end()) twice = *found;
  MPI_Allreduce(MPI_IN_PLACE, &twice, 1, MPI_UINT64_T, MPI_MIN, comm);
  int any = found != incoming.end();
  MPI_Allreduce(MPI_IN_PLACE, &any, 1, MPI_INT, MPI_LOR, comm);
  if (!any) return std::nullopt;
  return twice;
}

}  // namespace flecsi_lite::io
