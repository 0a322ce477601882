// Collective reader of H5Part files with parallel HDF5: lists the steps (in numeric order), the
// datasets and attributes of a step, and reads each rank's slice of a dataset collectively.
//
// By default rank r of p reads the balanced block block_slice(N, r, p) of a step's N particles
// (the seed's "read f in parallel"); an explicit slice reads any [offset, offset + count).
// Every member function is collective over the reader's communicator: errors (missing file,
// not HDF5, truncated, missing step or dataset, datasets of different lengths in one step, a
// declared length the file's bytes cannot hold, wrong element type, slice out of range) throw
// the same io_error subclass with the same message on every rank, naming the file, the step and
// the dataset. HDF5's own error printing is off.
#pragma once

#include "flecsi_lite/io/attribute_value.hh"
#include "flecsi_lite/io/detail/hdf5_handle.hh"
#include "flecsi_lite/io/detail/metadata_listing.hh"
#include "flecsi_lite/io/element_type.hh"
#include "flecsi_lite/io/particle_partition.hh"
#include "flecsi_lite/io/step_info.hh"
#include "flecsi_lite/runtime/context.hh"

#include <mpi.h>

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace flecsi_lite::io {

class h5part_reader {
 public:
  explicit h5part_reader(std::string path, MPI_Comm comm = runtime::communicator());
  h5part_reader(const h5part_reader&) = delete;
  h5part_reader& operator=(const h5part_reader&) = delete;
  ~h5part_reader();

  const std::string& path() const { return path_; }
  MPI_Comm communicator() const { return comm_; }

  /// Indices k of the groups Step#k, ascending (Step#10 after Step#9).
  const std::vector<std::int64_t>& steps() const { return steps_; }
  bool has_step(std::int64_t step) const;
  /// The highest step index; missing_step_error when the file has no step.
  std::int64_t last_step() const;

  std::vector<std::string> root_attribute_names() const;
  attribute_value root_attribute(const std::string& name) const;
  template<class T>
  T root_attribute_as(const std::string& name) const {
    return attribute_as<T>(root_attribute(name), "root attribute '" + name + "' of '" + path_ + "'");
  }
  std::vector<std::string> step_attribute_names(std::int64_t step) const;
  attribute_value step_attribute(std::int64_t step, const std::string& name) const;
  template<class T>
  T step_attribute_as(std::int64_t step, const std::string& name) const {
    return attribute_as<T>(step_attribute(step, name), describe_attribute(step, name));
  }
  /// time (TimeValue when there is no 'time'), step (the index when absent), dt (0 when absent).
  step_info step_information(std::int64_t step) const;

  /// Names of the datasets of a step, in name order.
  std::vector<std::string> datasets(std::int64_t step) const;
  bool has_dataset(std::int64_t step, const std::string& name) const;
  element_type dataset_type(std::int64_t step, const std::string& name) const;
  /// The common length of every dataset of the step (0 for a step without datasets).
  std::uint64_t particle_count(std::int64_t step) const;
  /// This rank's balanced block of the step's particles.
  slice block(std::int64_t step) const;

  /// This rank's block of dataset `name` of `step`; T must be the dataset's element type.
  template<class T>
  std::vector<T> read(std::int64_t step, const std::string& name) const {
    return read<T>(step, name, block(step));
  }
  /// Elements [part.offset, part.offset + part.count) of the dataset (each rank its own part).
  template<class T>
  std::vector<T> read(std::int64_t step, const std::string& name, slice part) const {
    std::vector<T> values(part.count);
    read_into(step, name, part, element_type_of<T>(), values.data());
    return values;
  }
  template<class T>
  void read_into(std::int64_t step, const std::string& name, slice part, T* out) const {
    read_into(step, name, part, element_type_of<T>(), out);
  }

 private:
  void read_into(std::int64_t step, const std::string& name, slice part, element_type type, void* out) const;
  hdf5_handle open_step(std::int64_t step) const;  // throws missing_step_error
  hdf5_handle open_dataset(std::int64_t step, const std::string& name) const;
  std::uint64_t checked_length(std::int64_t step) const;  // no MPI: for use inside agree()
  const std::vector<std::string>& dataset_names(std::int64_t step) const;
  void check_storable(hid_t dataset, std::uint64_t extent, const std::string& what) const;
  std::string describe_step(std::int64_t step) const;
  std::string describe_dataset(std::int64_t step, const std::string& name) const;
  std::string describe_attribute(std::int64_t step, const std::string& name) const;

  std::string path_;
  MPI_Comm comm_;
  hdf5_handle file_;
  metadata_listing listing_;  // the file's groups and datasets, from rank 0's forked check
  std::vector<std::int64_t> steps_;
  mutable std::map<std::int64_t, std::uint64_t> step_lengths_;  // checked lengths, by step
};

}  // namespace flecsi_lite::io
