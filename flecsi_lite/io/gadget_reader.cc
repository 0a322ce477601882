// Collective reader of GADGET/SWIFT-layout HDF5 files over parallel HDF5 (see gadget_reader.hh).
#include "flecsi_lite/io/gadget_reader.hh"

#include "flecsi_lite/io/collective_agreement.hh"
#include "flecsi_lite/io/detail/collective_open.hh"
#include "flecsi_lite/io/detail/h5part_precheck.hh"
#include "flecsi_lite/io/detail/hdf5_attributes.hh"
#include "flecsi_lite/io/detail/hdf5_errors.hh"
#include "flecsi_lite/io/detail/hdf5_parallel.hh"
#include "flecsi_lite/io/detail/hdf5_storage.hh"
#include "flecsi_lite/io/detail/rank_slice.hh"
#include "flecsi_lite/io/io_error.hh"
#include "flecsi_lite/util/edit_distance.hh"

#include <algorithm>
#include <filesystem>
#include <optional>
#include <utility>
#include <variant>

namespace flecsi_lite::io {

namespace {
bool has_link(hid_t location, const std::string& name) {
  return !name.empty() && H5Lexists(location, name.c_str(), H5P_DEFAULT) > 0;
}

// The dataspace extent of a dataset: {N} or {N, C}; layout_error for other ranks.
std::vector<hsize_t> extent_of(hid_t dataset, const std::string& what) {
  auto space = dataspace_handle(H5Dget_space(dataset));
  const int rank = space ? H5Sget_simple_extent_ndims(space.get()) : -1;
  if (rank < 0) throw file_error("cannot inspect " + what + hdf5_reason());
  if (rank != 1 && rank != 2)
    throw layout_error(what + " has " + std::to_string(rank) + " dimensions; particle datasets have N or N x C values");
  std::vector<hsize_t> extent(rank);
  H5Sget_simple_extent_dims(space.get(), extent.data(), nullptr);
  return extent;
}
}  // namespace

bool gadget_reader::has_gadget_layout(const std::string& path, MPI_Comm comm) {
  int found = 0;
  if (rank_of(comm) == 0) {
    hdf5_quiet_scope quiet;
    std::error_code error;
    // The groups come from the forked check (h5part_precheck.hh): this process iterates no link
    // table. A file the check finds damaged is left to the H5Part reader, which reports it.
    if (std::filesystem::is_regular_file(path, error) && H5Fis_hdf5(path.c_str()) > 0) {
      const auto check = h5part::check_metadata(path);
      const auto& groups = check.listing.groups;
      const auto has_group = [&](const char* name) {
        return std::find(groups.begin(), groups.end(), name) != groups.end();
      };
      found = check.problem.empty() && has_group("Header") && has_group("PartType0");
    }
  }
  MPI_Bcast(&found, 1, MPI_INT, 0, comm);
  return found != 0;
}

std::string gadget_reader::text_attribute(const std::string& path, const std::string& group, const std::string& name) {
  hdf5_quiet_scope quiet;
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error) || H5Fis_hdf5(path.c_str()) <= 0) return "";
  auto file = file_handle(H5Fopen(path.c_str(), H5F_ACC_RDONLY, H5P_DEFAULT));
  if (!file || !has_link(file.get(), group) ||
      H5Aexists_by_name(file.get(), group.c_str(), name.c_str(), H5P_DEFAULT) <= 0)
    return "";
  auto location = object_handle(H5Oopen(file.get(), group.c_str(), H5P_DEFAULT));
  try {
    const auto value = read_attribute(location.get(), name, "attribute " + group + "/" + name + " of '" + path + "'");
    if (const auto* text = std::get_if<std::string>(&value)) return *text;
  } catch (const io_error&) {}
  return "";
}

gadget_reader::gadget_reader(std::string path, std::string group, std::map<std::string, column> columns, MPI_Comm comm)
    : path_(std::move(path)), group_(std::move(group)), columns_(std::move(columns)), comm_(comm) {
  hdf5_quiet_scope quiet;
  auto opened = open_for_reading_collectively(path_, comm_, "a SWIFT snapshot");
  file_ = std::move(opened.file);
  const auto& groups = opened.listing.groups;
  agree(comm_, [&] {
    if (std::find(groups.begin(), groups.end(), group_) == groups.end())
      throw missing_dataset_error("'" + path_ + "' has no group " + group_ + " (its particles)");
    particles_ = group_handle(H5Gopen2(file_.get(), group_.c_str(), H5P_DEFAULT));
    if (!particles_) throw file_error("cannot open " + group_ + " of '" + path_ + "'" + hdf5_reason());
    std::string first;
    // The datasets as the forked check listed them (metadata_listing.hh): no link iteration here.
    for (const auto& name : opened.listing.datasets_of(group_)) {
      auto dataset = dataset_handle(H5Dopen2(particles_.get(), name.c_str(), H5P_DEFAULT));
      if (!dataset) throw file_error("cannot open " + describe(name) + hdf5_reason());
      datasets_.push_back(name);
      const auto extent = extent_of(dataset.get(), describe(name));
      auto type = datatype_handle(H5Dget_type(dataset.get()));
      const std::uint64_t element_size = type ? H5Tget_size(type.get()) * (extent.size() == 2 ? extent[1] : 1) : 0;
      const std::uint64_t file_size = file_size_of(dataset.get());
      if (element_size > 0 && file_size > 0 && extent[0] > storable_elements(dataset.get(), element_size, file_size))
        throw file_error(describe(name) + " declares " + std::to_string(extent[0]) +
                         " particles, more than the file's " + std::to_string(file_size) +
                         " bytes can hold: the file is corrupted");
      if (!first.empty() && extent[0] != count_)
        throw layout_error(group_ + " of '" + path_ + "' has datasets of different lengths: '" + first + "' has " +
                           std::to_string(count_) + " particles, '" + name + "' has " + std::to_string(extent[0]));
      if (first.empty()) first = name, count_ = extent[0];
    }
  });
}

gadget_reader::~gadget_reader() {
  hdf5_quiet_scope quiet;
  particles_.close();
  file_.close();
}

std::string gadget_reader::where() const { return "'" + path_ + "' " + group_; }

std::string gadget_reader::describe(const std::string& dataset) const {
  return "dataset " + group_ + "/" + dataset + " of '" + path_ + "'";
}

bool gadget_reader::has_group(const std::string& group) const {
  hdf5_quiet_scope quiet;
  return has_link(file_.get(), group);
}

bool gadget_reader::has_attribute(const std::string& group, const std::string& name) const {
  hdf5_quiet_scope quiet;
  return has_link(file_.get(), group) && H5Aexists_by_name(file_.get(), group.c_str(), name.c_str(), H5P_DEFAULT) > 0;
}

std::vector<double> gadget_reader::numbers(const std::string& group, const std::string& name) const {
  hdf5_quiet_scope quiet;
  std::vector<double> values;
  agree(comm_, [&] {
    const std::string what = "attribute " + group + "/" + name + " of '" + path_ + "'";
    if (!has_link(file_.get(), group))
      throw missing_attribute_error("'" + path_ + "' has no group " + group + " (for " + what + ")");
    if (H5Aexists_by_name(file_.get(), group.c_str(), name.c_str(), H5P_DEFAULT) <= 0)
      throw missing_attribute_error("'" + path_ + "' has no " + what.substr(0, what.find(" of '")));
    auto attribute =
      attribute_handle(H5Aopen_by_name(file_.get(), group.c_str(), name.c_str(), H5P_DEFAULT, H5P_DEFAULT));
    auto type = datatype_handle(attribute ? H5Aget_type(attribute.get()) : H5I_INVALID_HID);
    auto space = dataspace_handle(attribute ? H5Aget_space(attribute.get()) : H5I_INVALID_HID);
    if (!type || !space) throw file_error("cannot inspect " + what + hdf5_reason());
    const H5T_class_t kind = H5Tget_class(type.get());
    if (kind != H5T_INTEGER && kind != H5T_FLOAT)
      throw element_type_error(what + " holds " + describe_datatype(type.get()) + " values, not numbers");
    const hssize_t n = H5Sget_simple_extent_npoints(space.get());
    if (n <= 0 || n > 4096) throw layout_error(what + " has " + std::to_string(n) + " values");
    values.resize(static_cast<std::size_t>(n));
    if (H5Aread(attribute.get(), H5T_NATIVE_DOUBLE, values.data()) < 0)
      throw file_error("cannot read " + what + hdf5_reason());
  });
  return values;
}

slice gadget_reader::block() const {
  int size = 1;
  MPI_Comm_size(comm_, &size);
  return block_slice(count_, rank_of(comm_), size);
}

const gadget_reader::column& gadget_reader::column_of(const std::string& name) const {
  const auto found = columns_.find(name);
  if (found == columns_.end()) throw usage_error("no column '" + name + "' is named for " + where());
  return found->second;
}

bool gadget_reader::has_column(const std::string& name) const {
  const auto found = columns_.find(name);
  return found != columns_.end() &&
         std::find(datasets_.begin(), datasets_.end(), found->second.dataset) != datasets_.end();
}

hdf5_handle gadget_reader::open_dataset(const std::string& name) const {
  const column& c = column_of(name);
  if (std::find(datasets_.begin(), datasets_.end(), c.dataset) == datasets_.end()) {
    std::string message = "'" + path_ + "' has no dataset " + group_ + "/" + c.dataset + " (read as " + name + ")";
    if (const auto near = util::nearest_name(c.dataset, datasets_); !near.empty())
      message += "; did you mean '" + near + "'?";
    std::string list;
    for (const auto& n : datasets_) list += (list.empty() ? "" : " ") + n;
    throw missing_dataset_error(message + " (datasets: " + (list.empty() ? "none" : list) + ")");
  }
  auto dataset = dataset_handle(H5Dopen2(particles_.get(), c.dataset.c_str(), H5P_DEFAULT));
  if (!dataset) throw file_error("cannot open " + describe(c.dataset) + hdf5_reason());
  const auto extent = extent_of(dataset.get(), describe(c.dataset));
  const hsize_t columns = extent.size() == 2 ? extent[1] : 1;
  if (c.component < 0 || static_cast<hsize_t>(c.component) >= columns)
    throw layout_error(describe(c.dataset) + " has " + std::to_string(columns) + " columns; " + name + " is column " +
                       std::to_string(c.component));
  return dataset;
}

element_type gadget_reader::column_type(const std::string& name) const {
  hdf5_quiet_scope quiet;
  element_type type = element_type::unsupported;
  agree(comm_, [&] {
    auto dataset = open_dataset(name);
    auto stored = datatype_handle(H5Dget_type(dataset.get()));
    if (!stored) throw file_error("cannot inspect " + describe(column_of(name).dataset) + hdf5_reason());
    type = classify(stored.get());
  });
  return type;
}

void gadget_reader::read_column(const std::string& name, slice part, element_type type, void* out) const {
  hdf5_quiet_scope quiet;
  hdf5_handle dataset, file_space, memory_space;
  agree(comm_, [&] {
    dataset = open_dataset(name);
    const std::string what = describe(column_of(name).dataset);
    auto stored = datatype_handle(H5Dget_type(dataset.get()));
    if (!stored) throw file_error("cannot inspect " + what + hdf5_reason());
    if (classify(stored.get()) != type)
      throw element_type_error(what + " holds " + describe_datatype(stored.get()) + " values, not " +
                               element_type_name(type));
    if (part.offset > count_ || part.count > count_ - part.offset)
      throw slice_error(what + " has " + std::to_string(count_) + " particles; rank " + std::to_string(rank_of(comm_)) +
                        " asked for [" + std::to_string(part.offset) + ", " + std::to_string(part.offset + part.count) +
                        ")");
    auto slice = select_rank_slice(dataset.get(), part.offset, part.count,
                                   static_cast<hsize_t>(column_of(name).component), 1, 1, what);
    file_space = std::move(slice.file_space);
    memory_space = std::move(slice.memory_space);
  });
  // Collective: every rank takes part, those that read nothing with an empty selection.
  auto transfer = collective_transfer();
  char nothing = 0;
  std::optional<failure_record> failed;
  if (count_ > 0 && H5Dread(dataset.get(), memory_type(type), memory_space.get(), file_space.get(), transfer.get(),
                            part.count > 0 ? out : &nothing) < 0)
    failed = failure_record{failure::file, "cannot read " + describe(column_of(name).dataset) + hdf5_reason()};
  raise_if_any(comm_, failed);
}

}  // namespace flecsi_lite::io
