// Collective H5Part reader over parallel HDF5 (see h5part_reader.hh).
#include "flecsi_lite/io/h5part_reader.hh"

#include "flecsi_lite/io/collective_agreement.hh"
#include "flecsi_lite/io/detail/collective_open.hh"
#include "flecsi_lite/io/detail/h5part_layout.hh"
#include "flecsi_lite/io/detail/h5part_steps.hh"
#include "flecsi_lite/io/detail/hdf5_attributes.hh"
#include "flecsi_lite/io/detail/hdf5_errors.hh"
#include "flecsi_lite/io/detail/hdf5_parallel.hh"
#include "flecsi_lite/io/detail/hdf5_storage.hh"
#include "flecsi_lite/io/detail/rank_slice.hh"
#include "flecsi_lite/util/edit_distance.hh"

#include <algorithm>
#include <optional>
#include <utility>

namespace flecsi_lite::io {

namespace {
int size_of(MPI_Comm comm) {
  int size = 1;
  MPI_Comm_size(comm, &size);
  return size;
}

std::string describe_steps(const std::vector<std::int64_t>& steps) {
  if (steps.empty()) return "it has no steps";
  if (steps.back() - steps.front() + 1 == static_cast<std::int64_t>(steps.size()))
    return "it has steps " + std::to_string(steps.front()) + " to " + std::to_string(steps.back());
  std::string list = "it has steps";
  for (std::size_t k = 0; k < steps.size() && k < 8; ++k) list += (k ? ", " : " ") + std::to_string(steps[k]);
  return steps.size() > 8 ? list + ", ..." : list;
}

}  // namespace

h5part_reader::h5part_reader(std::string path, MPI_Comm comm) : path_(std::move(path)), comm_(comm) {
  hdf5_quiet_scope quiet;
  auto opened = open_for_reading_collectively(path_, comm_, "an H5Part file");
  file_ = std::move(opened.file);
  listing_ = std::move(opened.listing);
  steps_ = h5part::step_indices(listing_.groups);
}

h5part_reader::~h5part_reader() {
  hdf5_quiet_scope quiet;
  file_.close();
}

bool h5part_reader::has_step(std::int64_t step) const { return std::binary_search(steps_.begin(), steps_.end(), step); }

std::int64_t h5part_reader::last_step() const {
  if (steps_.empty()) throw missing_step_error("'" + path_ + "' has no steps");
  return steps_.back();
}

std::string h5part_reader::describe_step(std::int64_t step) const {
  return "step " + std::to_string(step) + " of '" + path_ + "'";
}

std::string h5part_reader::describe_dataset(std::int64_t step, const std::string& name) const {
  return "dataset '" + name + "' of " + describe_step(step);
}

std::string h5part_reader::describe_attribute(std::int64_t step, const std::string& name) const {
  return "attribute '" + name + "' of " + describe_step(step);
}

hdf5_handle h5part_reader::open_step(std::int64_t step) const {
  if (!has_step(step))
    throw missing_step_error("'" + path_ + "' has no step " + std::to_string(step) + " (" + describe_steps(steps_) +
                             ")");
  auto group = group_handle(H5Gopen2(file_.get(), h5part::step_group_name(step).c_str(), H5P_DEFAULT));
  if (!group) throw file_error("cannot open " + describe_step(step) + hdf5_reason());
  return group;
}

// Names of the datasets of the step, in name order, as the forked check listed them.
const std::vector<std::string>& h5part_reader::dataset_names(std::int64_t step) const {
  return listing_.datasets_of(h5part::step_group_name(step));
}

hdf5_handle h5part_reader::open_dataset(std::int64_t step, const std::string& name) const {
  auto group = open_step(step);
  if (!name.empty() && H5Lexists(group.get(), name.c_str(), H5P_DEFAULT) > 0) {
    auto object = object_handle(H5Oopen(group.get(), name.c_str(), H5P_DEFAULT));
    if (object && H5Iget_type(object.get()) == H5I_DATASET) return object;
  }
  const auto& names = dataset_names(step);
  std::string message = describe_step(step) + " has no dataset '" + name + "'";
  if (const auto near = util::nearest_name(name, names); !near.empty()) message += "; did you mean '" + near + "'?";
  std::string list;
  for (const auto& n : names) list += (list.empty() ? "" : " ") + n;
  throw missing_dataset_error(message + " (datasets: " + (list.empty() ? "none" : list) + ")");
}

// Before anything is allocated for it: a declared extent the file's bytes cannot hold is
// corruption (a flipped bit in a dataspace declares 2^60 particles).
void h5part_reader::check_storable(hid_t dataset, std::uint64_t extent, const std::string& what) const {
  auto type = datatype_handle(H5Dget_type(dataset));
  const std::uint64_t element_size = type ? H5Tget_size(type.get()) : 0;
  if (element_size == 0) throw file_error("cannot inspect " + what + hdf5_reason());
  const std::uint64_t file_size = file_size_of(dataset);
  if (file_size > 0 && extent > storable_elements(dataset, element_size, file_size))
    throw file_error(what + " declares " + std::to_string(extent) + " particles of " + std::to_string(element_size) +
                     " bytes, more than the file's " + std::to_string(file_size) +
                     " bytes can hold: the file is corrupted");
}

std::uint64_t h5part_reader::checked_length(std::int64_t step) const {
  if (auto known = step_lengths_.find(step); known != step_lengths_.end()) return known->second;
  auto group = open_step(step);
  std::optional<std::uint64_t> length;
  std::string first;
  for (const auto& name : dataset_names(step)) {
    auto dataset = dataset_handle(H5Dopen2(group.get(), name.c_str(), H5P_DEFAULT));
    auto space = dataspace_handle(dataset ? H5Dget_space(dataset.get()) : H5I_INVALID_HID);
    if (!space) throw file_error("cannot open " + describe_dataset(step, name) + hdf5_reason());
    const int rank = H5Sget_simple_extent_ndims(space.get());
    hsize_t extent = 0;
    if (rank != 1 || H5Sget_simple_extent_dims(space.get(), &extent, nullptr) != 1)
      throw layout_error(describe_dataset(step, name) + " has " + std::to_string(rank) +
                         " dimensions; H5Part datasets are 1-D");
    check_storable(dataset.get(), extent, describe_dataset(step, name));
    if (length && *length != extent)
      throw layout_error(describe_step(step) + " has datasets of different lengths: '" + first + "' has " +
                         std::to_string(*length) + " particles, '" + name + "' has " + std::to_string(extent));
    if (!length) length = extent, first = name;
  }
  step_lengths_[step] = length.value_or(0);
  return length.value_or(0);
}

std::vector<std::string> h5part_reader::root_attribute_names() const {
  hdf5_quiet_scope quiet;
  std::vector<std::string> names;
  agree(comm_, [&] { names = attribute_names(file_.get()); });
  return names;
}

attribute_value h5part_reader::root_attribute(const std::string& name) const {
  hdf5_quiet_scope quiet;
  attribute_value value;
  agree(comm_, [&] {
    const std::string what = "root attribute '" + name + "' of '" + path_ + "'";
    if (!has_attribute(file_.get(), name)) {
      std::string message = "'" + path_ + "' has no root attribute '" + name + "'";
      if (auto near = util::nearest_name(name, attribute_names(file_.get())); !near.empty())
        message += "; did you mean '" + near + "'?";
      throw missing_attribute_error(message);
    }
    value = read_attribute(file_.get(), name, what);
  });
  return value;
}

std::vector<std::string> h5part_reader::step_attribute_names(std::int64_t step) const {
  hdf5_quiet_scope quiet;
  std::vector<std::string> names;
  agree(comm_, [&] { names = attribute_names(open_step(step).get()); });
  return names;
}

attribute_value h5part_reader::step_attribute(std::int64_t step, const std::string& name) const {
  hdf5_quiet_scope quiet;
  attribute_value value;
  agree(comm_, [&] {
    auto group = open_step(step);
    if (!has_attribute(group.get(), name)) {
      std::string message = describe_step(step) + " has no attribute '" + name + "'";
      if (auto near = util::nearest_name(name, attribute_names(group.get())); !near.empty())
        message += "; did you mean '" + near + "'?";
      throw missing_attribute_error(message);
    }
    value = read_attribute(group.get(), name, describe_attribute(step, name));
  });
  return value;
}

step_info h5part_reader::step_information(std::int64_t step) const {
  hdf5_quiet_scope quiet;
  step_info info;
  agree(comm_, [&] {
    auto group = open_step(step);
    const auto real = [&](const char* name, double fallback) {
      if (!has_attribute(group.get(), name)) return fallback;
      return attribute_as<double>(read_attribute(group.get(), name, describe_attribute(step, name)),
                                  describe_attribute(step, name));
    };
    info.time = real(h5part::attribute::time, real(h5part::attribute::time_value, 0.0));
    info.dt = real(h5part::attribute::dt, 0.0);
    info.step = has_attribute(group.get(), h5part::attribute::step)
                  ? attribute_as<std::int64_t>(read_attribute(group.get(), h5part::attribute::step,
                                                              describe_attribute(step, h5part::attribute::step)),
                                               describe_attribute(step, h5part::attribute::step))
                  : step;
  });
  return info;
}

std::vector<std::string> h5part_reader::datasets(std::int64_t step) const {
  hdf5_quiet_scope quiet;
  std::vector<std::string> names;
  agree(comm_, [&] {
    open_step(step);  // missing_step_error
    names = dataset_names(step);
  });
  return names;
}

bool h5part_reader::has_dataset(std::int64_t step, const std::string& name) const {
  const auto names = datasets(step);
  return std::find(names.begin(), names.end(), name) != names.end();
}

element_type h5part_reader::dataset_type(std::int64_t step, const std::string& name) const {
  hdf5_quiet_scope quiet;
  element_type type = element_type::unsupported;
  agree(comm_, [&] {
    auto dataset = open_dataset(step, name);
    auto stored = datatype_handle(H5Dget_type(dataset.get()));
    if (!stored) throw file_error("cannot inspect " + describe_dataset(step, name) + hdf5_reason());
    type = classify(stored.get());
  });
  return type;
}

std::uint64_t h5part_reader::particle_count(std::int64_t step) const {
  hdf5_quiet_scope quiet;
  std::uint64_t length = 0;
  agree(comm_, [&] { length = checked_length(step); });
  return length;
}

slice h5part_reader::block(std::int64_t step) const {
  return block_slice(particle_count(step), rank_of(comm_), size_of(comm_));
}

void h5part_reader::read_into(std::int64_t step, const std::string& name, slice part, element_type type,
                              void* out) const {
  hdf5_quiet_scope quiet;
  hdf5_handle dataset, file_space, memory_space;
  std::uint64_t length = 0;
  agree(comm_, [&] {
    dataset = open_dataset(step, name);
    length = checked_length(step);
    auto stored = datatype_handle(H5Dget_type(dataset.get()));
    if (!stored) throw file_error("cannot inspect " + describe_dataset(step, name) + hdf5_reason());
    if (classify(stored.get()) != type)
      throw element_type_error(describe_dataset(step, name) + " holds " + describe_datatype(stored.get()) +
                               " values, not " + element_type_name(type));
    if (part.offset > length || part.count > length - part.offset)
      throw slice_error(describe_dataset(step, name) + " has " + std::to_string(length) + " particles; rank " +
                        std::to_string(rank_of(comm_)) + " asked for [" + std::to_string(part.offset) + ", " +
                        std::to_string(part.offset + part.count) + ")");
    auto slice = select_rank_slice(dataset.get(), part.offset, part.count, 0, 1, 1, describe_dataset(step, name));
    file_space = std::move(slice.file_space);
    memory_space = std::move(slice.memory_space);
  });
  // Collective: every rank takes part, those that read nothing with an empty selection. A
  // dataset without any element has no storage to read from (the same on every rank).
  auto transfer = collective_transfer();
  char nothing = 0;
  std::optional<failure_record> failed;
  if (length > 0 && H5Dread(dataset.get(), memory_type(type), memory_space.get(), file_space.get(), transfer.get(),
                            part.count > 0 ? out : &nothing) < 0)
    failed = failure_record{failure::file, "cannot read " + describe_dataset(step, name) + hdf5_reason()};
  raise_if_any(comm_, failed);
}

}  // namespace flecsi_lite::io
