// Collective writer of GADGET/SWIFT-layout particle snapshots over parallel HDF5 (see
// snapshot_writer.hh); the failure handling is h5part_writer's (hdf5/partial_file.hh).
#include "flecsi_lite/io/snapshot_writer.hh"

#include "flecsi_lite/io/collective_agreement.hh"
#include "flecsi_lite/io/detail/hdf5_attributes.hh"
#include "flecsi_lite/io/detail/hdf5_errors.hh"
#include "flecsi_lite/io/detail/hdf5_parallel.hh"
#include "flecsi_lite/io/detail/partial_file.hh"
#include "flecsi_lite/io/detail/rank_slice.hh"
#include "flecsi_lite/io/output_path.hh"
#include "flecsi_lite/io/particle_partition.hh"
#include "flecsi_lite/runtime/log.hh"

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <optional>
#include <utility>

namespace flecsi_lite::io {

namespace {
// The file and memory types of each kind of attribute array.
template<class T>
std::pair<hid_t, hid_t> attribute_types() {
  if constexpr (std::is_same_v<T, std::int32_t>)
    return {H5T_STD_I32LE, H5T_NATIVE_INT32};
  else if constexpr (std::is_same_v<T, std::uint32_t>)
    return {H5T_STD_U32LE, H5T_NATIVE_UINT32};
  else if constexpr (std::is_same_v<T, std::int64_t>)
    return {H5T_STD_I64LE, H5T_NATIVE_INT64};
  else if constexpr (std::is_same_v<T, float>)
    return {H5T_IEEE_F32LE, H5T_NATIVE_FLOAT};
  else
    return {H5T_IEEE_F64LE, H5T_NATIVE_DOUBLE};
}

// Numbers as a 1-D array (H5Screate_simple of their count), text as a scalar fixed-length string,
// both as SWIFT's io_write_attribute and io_writeStringAttribute write them (src/common_io.c).
void write_snapshot_attribute(hid_t location, const snapshot_attribute& attribute, const std::string& where) {
  const auto fail = [&] {
    throw io_error(failure::system, "cannot write attribute '" + attribute.name + "' of " + where + hdf5_reason());
  };
  if (has_attribute(location, attribute.name) && H5Adelete(location, attribute.name.c_str()) < 0) fail();
  std::visit(
    [&](const auto& value) {
      using V = std::decay_t<decltype(value)>;
      hdf5_handle space, string_type;
      hid_t stored, in_memory;
      const void* data;
      if constexpr (std::is_same_v<V, std::string>) {
        space = dataspace_handle(H5Screate(H5S_SCALAR));
        string_type = datatype_handle(H5Tcopy(H5T_C_S1));
        if (!string_type || H5Tset_size(string_type.get(), std::max<std::size_t>(value.size(), 1)) < 0) fail();
        stored = in_memory = string_type.get();
        data = value.empty() ? "" : value.c_str();
      } else {
        const hsize_t count = value.size();
        space = dataspace_handle(H5Screate_simple(1, &count, nullptr));
        std::tie(stored, in_memory) = attribute_types<typename V::value_type>();
        data = value.data();
      }
      auto handle =
        attribute_handle(H5Acreate2(location, attribute.name.c_str(), stored, space.get(), H5P_DEFAULT, H5P_DEFAULT));
      if (!space || !handle || H5Awrite(handle.get(), in_memory, data) < 0) fail();
    },
    attribute.value);
}

// The exact bytes of attributes, to check that every rank passes the same ones.
std::string fingerprint(const snapshot_attributes& attributes) {
  std::string bytes;
  for (const auto& attribute : attributes) {
    bytes += attribute.name + '\0' + std::to_string(attribute.value.index()) + '\0';
    std::visit(
      [&](const auto& value) {
        using V = std::decay_t<decltype(value)>;
        if constexpr (std::is_same_v<V, std::string>)
          bytes += value;
        else
          bytes.append(reinterpret_cast<const char*>(value.data()), value.size() * sizeof(value[0]));
      },
      attribute.value);
    bytes += '\0';
  }
  return bytes;
}

bool valid_name(const std::string& name) { return !name.empty() && name != "." && name.find('/') == std::string::npos; }

hdf5_handle untimed_creation(hid_t class_id) {
  // No modification times: identical runs write identical files.
  auto creation = property_list_handle(H5Pcreate(class_id));
  if (!creation || H5Pset_obj_track_times(creation.get(), false) < 0)
    throw io_error(failure::system, "cannot describe an HDF5 object" + hdf5_reason());
  return creation;
}
}  // namespace

snapshot_writer::snapshot_writer(std::string path, MPI_Comm comm)
    : path_(std::move(path)), comm_(comm), output_(path_, comm) {
  hdf5_quiet_scope quiet;
  agree(comm_, [&] {
    if (rank_of(comm_) != 0) return;
    require_replaceable(path_);
    require_replaceable(partial_path(), "temporary file");
  });
  const std::string name = mpi_io_name(partial_path());  // the same verdict on every rank
  auto access = mpio_file_access(comm_);
  auto creation = untimed_creation(H5P_FILE_CREATE);
  const hid_t id = H5Fcreate(name.c_str(), H5F_ACC_TRUNC, creation.get(), access.get());
  std::optional<failure_record> failed;
  if (id < 0)
    failed = failure_record{failure::file, "cannot create '" + partial_path() + "' for writing" + hdf5_reason()};
  output_.file() = file_handle(id);
  try {
    raise_if_any(comm_, failed);
  } catch (...) {
    output_.file().release();  // a parallel close on only the ranks that opened it would never return
    throw;
  }
}

snapshot_writer::~snapshot_writer() { abandon(); }

void snapshot_writer::abandon() noexcept {
  if (output_.awaits_commit()) {
    if (rank_of(comm_) == 0)
      log::warn() << "snapshot: '" << path_ << "' was left unchanged; the complete snapshot is in '" << partial_path()
                  << "'";
    return;
  }
  if (!is_open()) return;
  try {
    // An unfinished snapshot is of no use to anyone: removed in every case.
    output_.close_unfinished();
    if (rank_of(comm_) == 0) {
      std::error_code error;
      std::filesystem::remove(partial_path(), error);
      log::warn() << "snapshot: '" << path_ << "' was not completed: '" << partial_path() << "' removed, '" << path_
                  << "' unchanged";
    }
    MPI_Barrier(comm_);  // every rank returns with the partial file gone
  } catch (...) {}
}

void snapshot_writer::require_open(const char* operation) const {
  if (!is_open()) throw usage_error(std::string(operation) + ": the snapshot writer of '" + path_ + "' is closed");
}

hdf5_handle snapshot_writer::open_group(const std::string& group) {
  if (group.empty()) return group_handle(H5Gopen2(output_.file().get(), "/", H5P_DEFAULT));
  if (!valid_name(group)) throw usage_error("'" + group + "' is not a valid group name (in '" + path_ + "')");
  const htri_t exists = H5Lexists(output_.file().get(), group.c_str(), H5P_DEFAULT);
  auto handle = exists > 0 ? group_handle(H5Gopen2(output_.file().get(), group.c_str(), H5P_DEFAULT))
                           : group_handle(H5Gcreate2(output_.file().get(), group.c_str(), H5P_DEFAULT,
                                                     untimed_creation(H5P_GROUP_CREATE).get(), H5P_DEFAULT));
  if (!handle)
    throw io_error(failure::system, "cannot create group " + group + " in '" + partial_path() + "'" + hdf5_reason());
  return handle;
}

void snapshot_writer::set_attributes(const std::string& group, const snapshot_attributes& attributes) {
  hdf5_quiet_scope quiet;
  if (!same_on_all_ranks(comm_, group + '\0' + fingerprint(attributes)))
    throw layout_error("ranks set different attributes (or values) of group '" + group + "' in '" + path_ + "'");
  agree(comm_, [&] {
    require_open("set_attributes");
    auto handle = open_group(group);
    for (const auto& attribute : attributes) {
      if (attribute.name.empty()) throw usage_error("an attribute of group '" + group + "' has no name");
      write_snapshot_attribute(handle.get(), attribute, "group '" + group + "' in '" + path_ + "'");
    }
  });
}

void snapshot_writer::write_array(const std::string& group, const std::string& name, element_type type,
                                  const void* data, std::size_t local_rows, int columns,
                                  const snapshot_attributes& attributes) {
  hdf5_quiet_scope quiet;
  const std::string where = "dataset '" + group + "/" + name + "' in '" + path_ + "'";
  agree(comm_, [&] {
    require_open("write");
    if (!valid_name(name) || !valid_name(group)) throw usage_error("write: " + where + ": not a valid name");
    if (columns < 1) throw usage_error("write " + where + ": " + std::to_string(columns) + " columns");
    if (datasets_.count(group + "/" + name)) throw usage_error("write: " + where + " is already written");
    if (local_rows > 0 && data == nullptr) throw usage_error("write " + where + ": no data");
  });
  if (!same_on_all_ranks(comm_, group + '\0' + name + '\0' + element_type_name(type) + '\0' + std::to_string(columns) +
                                  '\0' + fingerprint(attributes)))
    throw layout_error(
      "ranks write different datasets (names, types, columns or attributes differ) at the same "
      "point of '" +
      path_ + "'");
  const placement place = place_contiguously(comm_, local_rows);

  hdf5_handle dataset, file_space, memory_space;
  agree(comm_, [&] {
    const int rank = columns == 1 ? 1 : 2;
    const hsize_t global[2] = {place.global_length, hsize_t(columns)};
    auto group_of = open_group(group);
    auto global_space = dataspace_handle(H5Screate_simple(rank, global, nullptr));
    auto creation = untimed_creation(H5P_DATASET_CREATE);
    // Every element is written below: no fill value needed.
    if (!global_space || H5Pset_fill_time(creation.get(), H5D_FILL_TIME_NEVER) < 0)
      throw io_error(failure::system, "cannot describe " + where + hdf5_reason());
    dataset = dataset_handle(H5Dcreate2(group_of.get(), name.c_str(), file_type(type), global_space.get(), H5P_DEFAULT,
                                        creation.get(), H5P_DEFAULT));
    if (!dataset) throw io_error(failure::system, "cannot create " + where + hdf5_reason());
    for (const auto& attribute : attributes) write_snapshot_attribute(dataset.get(), attribute, where);
    auto slice =
      select_rank_slice(dataset.get(), place.local.offset, place.local.count, 0, hsize_t(columns), rank, where);
    file_space = std::move(slice.file_space);
    memory_space = std::move(slice.memory_space);
  });

  // Collective: every rank takes part, those without rows with an empty selection.
  auto transfer = collective_transfer();
  const char nothing[8] = {};
  std::optional<failure_record> failed;
  if (place.global_length > 0 && H5Dwrite(dataset.get(), memory_type(type), memory_space.get(), file_space.get(),
                                          transfer.get(), local_rows > 0 ? data : nothing) < 0)
    failed = failure_record{failure::system, "cannot write " + where + hdf5_reason()};
  output_.raise_marking_storage_failure(failed);
  datasets_.insert(group + "/" + name);
}

void snapshot_writer::finish() {
  if (!is_open()) return;
  output_.finish();  // a failed flush leaves the file open for abandon()
}

void snapshot_writer::commit() { output_.commit(); }

void snapshot_writer::close() {
  finish();
  commit();
}

}  // namespace flecsi_lite::io
