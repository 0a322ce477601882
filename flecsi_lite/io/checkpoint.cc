// Checkpoint writing and reading on top of the H5Part writer and reader (see checkpoint.hh).
#include "flecsi_lite/io/checkpoint.hh"

#include <algorithm>

namespace flecsi_lite::io {

void write_checkpoint(const std::string& path, const step_info& info, const run_state& state,
                      const std::function<void(h5part_writer&)>& write_arrays, MPI_Comm comm) {
  h5part_writer writer(path, comm);
  writer.set_attribute(checkpoint_marker, std::int64_t{1});
  for (const auto& [name, value] : state)
    writer.set_attribute(checkpoint_state_prefix + name, value);
  writer.begin_step(info);
  write_arrays(writer);
  writer.end_step();
  writer.close();
}

checkpoint_contents read_checkpoint(const h5part_reader& reader) {
  const auto names = reader.root_attribute_names();
  if (std::find(names.begin(), names.end(), checkpoint_marker) == names.end() || !reader.has_step(0))
    throw file_error("'" + reader.path() + "' is not a checkpoint (no root attribute '" +
                     checkpoint_marker + "' or no Step#0)");
  checkpoint_contents contents;
  contents.info = reader.step_information(0);
  const std::string prefix = checkpoint_state_prefix;
  for (const auto& name : names)
    if (name.compare(0, prefix.size(), prefix) == 0)
      contents.state[name.substr(prefix.size())] = reader.root_attribute(name);
  return contents;
}

} // namespace flecsi_lite::io
