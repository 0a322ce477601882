// Checkpoint writing and reading on top of the H5Part writer and reader (see checkpoint.hh).
#include "flecsi_lite/io/checkpoint.hh"

#include "flecsi_lite/io/run_state_checksums.hh"

#include <algorithm>
#include <cstring>
#include <limits>
#include <vector>

namespace flecsi_lite::io {

namespace {
/// The clock's attribute names in Step#0, as the checksum lines name them.
constexpr const char* clock_attributes[] = {"time", "step", "dt"};

/// The run state under checksum: its entries as "state:<name>" (their root attribute names).
checked_values state_values(const run_state& state) {
  checked_values values;
  for (const auto& [name, value] : state) values[checkpoint_state_prefix + name] = value;
  return values;
}
}  // namespace

void write_checkpoint(const std::string& path, const step_info& info, const run_state& state,
                      const std::function<void(h5part_writer&)>& write_arrays, MPI_Comm comm) {
  h5part_writer writer(path, comm);
  writer.set_attribute(checkpoint_marker, std::int64_t{1});
  for (const auto& [name, value] : state) writer.set_attribute(checkpoint_state_prefix + name, value);
  // The clock as begin_step writes it: time and dt doubles, step a 64-bit integer.
  checked_values values = state_values(state);
  values["time"] = info.time;
  values["step"] = info.step;
  values["dt"] = info.dt;
  writer.set_attribute(checksums_attribute, checksums_text(values));
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

void verify_run_state(const h5part_reader& reader, const checkpoint_contents& contents) {
  const std::string where = "checkpoint '" + reader.path() + "'";
  const auto names = reader.root_attribute_names();
  if (std::find(names.begin(), names.end(), checksums_attribute) == names.end())
    throw layout_error(where + " has no root attribute '" + checksums_attribute +
                       "': it was written before checkpoints held checksums of their run state (or the attribute was "
                       "removed), so a restart cannot tell a changed time, step or dt from the written one; make "
                       "the checkpoint again with this version (rerun from the start, or from initial_data)");
  const auto checksums =
    attribute_as<std::string>(reader.root_attribute(checksums_attribute), where + " root attribute 'checksums'");
  // The clock as the file holds it (not step_information's fallbacks: a missing 'time' is a change).
  checked_values values = state_values(contents.state);
  const auto step_names = reader.step_attribute_names(0);
  for (const char* name : clock_attributes)
    if (std::find(step_names.begin(), step_names.end(), name) != step_names.end())
      values[name] = reader.step_attribute(0, name);
  const auto changed = changed_values(checksums, values);
  if (changed.empty()) return;
  std::string list;
  for (const auto& name : changed) {
    const bool clock = name.compare(0, std::strlen(checkpoint_state_prefix), checkpoint_state_prefix) != 0;
    list += (list.empty() ? "" : ", ") + std::string(clock ? "Step#0 attribute '" : "root attribute '") + name + "'";
  }
  throw layout_error(where + ": " + list + (changed.size() == 1 ? " differs" : " differ") +
                     " from the value the writing run stored (root attribute 'checksums'): a restart from a changed "
                     "run state would not continue that run");
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
