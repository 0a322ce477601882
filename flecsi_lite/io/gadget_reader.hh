// Collective reader of GADGET/SWIFT-layout HDF5 files (GADGET-2's HDF5 format, as SWIFT's
// snapshots and the initial conditions of its examples' makeIC.py scripts hold it): the numeric
// attributes of a group (Header/NumPart_Total, Units/..., single numbers or arrays), and one
// particle group (PartType0, ...) as particle columns, each a dataset of N values or one column
// of an N x C dataset (Coordinates[:, 1] as y), each rank reading its balanced block.
//
// The caller names the columns (io knows no physics): {"y", {"Coordinates", 1}}. Errors (no such
// file, not HDF5, no group, a missing dataset or attribute, datasets of different lengths, a
// component beyond a dataset's columns) throw the same io_error on every rank, naming the file,
// the group and the dataset or attribute.
#pragma once

#include "flecsi_lite/io/column_source.hh"
#include "flecsi_lite/io/detail/hdf5_handle.hh"
#include "flecsi_lite/runtime/context.hh"

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace flecsi_lite::io {

class gadget_reader final : public column_source {
 public:
  /// Column `component` of dataset `dataset` (0 for a dataset of N values).
  struct column {
    std::string dataset;
    int component = 0;
  };

  /// Collective: opens `path` and its particle group `group`, whose datasets must all have one
  /// length (the particle count).
  gadget_reader(std::string path, std::string group, std::map<std::string, column> columns,
                MPI_Comm comm = runtime::communicator());
  gadget_reader(const gadget_reader&) = delete;
  gadget_reader& operator=(const gadget_reader&) = delete;
  ~gadget_reader() override;

  /// Collective: whether `path` is an HDF5 file with the groups Header and PartType0 (false for a
  /// missing or non-HDF5 file, or one whose metadata would crash libhdf5 (h5part_precheck.hh), which
  /// the H5Part reader then reports).
  static bool has_gadget_layout(const std::string& path, MPI_Comm comm = runtime::communicator());
  /// Serial (one rank, serial HDF5): the text attribute `group`/`name` of the file `path`, or ""
  /// when the file, the group or the attribute is missing or not text (Code/Code of a snapshot).
  static std::string text_attribute(const std::string& path, const std::string& group, const std::string& name);

  const std::string& path() const { return path_; }
  bool has_group(const std::string& group) const;
  bool has_attribute(const std::string& group, const std::string& name) const;
  /// The values of numeric attribute `name` of `group` (one or more) as doubles.
  std::vector<double> numbers(const std::string& group, const std::string& name) const;
  std::uint64_t particle_count() const { return count_; }

  std::string where() const override;
  MPI_Comm communicator() const override { return comm_; }
  slice block() const override;
  bool has_column(const std::string& name) const override;
  element_type column_type(const std::string& name) const override;

 protected:
  void read_column(const std::string& name, slice part, element_type type, void* out) const override;

 private:
  const column& column_of(const std::string& name) const;   // usage_error for an unnamed column
  hdf5_handle open_dataset(const std::string& name) const;  // the column's dataset, or throws
  std::string describe(const std::string& dataset) const;

  std::string path_, group_;
  std::map<std::string, column> columns_;
  MPI_Comm comm_;
  hdf5_handle file_, particles_;
  std::vector<std::string> datasets_;
  std::uint64_t count_ = 0;
};

}  // namespace flecsi_lite::io
