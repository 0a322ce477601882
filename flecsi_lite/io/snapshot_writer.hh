// Collective writer of one particle snapshot file in the GADGET-2 / SWIFT HDF5 layout (Springel
// 2005, GADGET-2 user guide sec. 6.2; Schaller et al. 2024, SWIFT's snapshot format) over parallel HDF5.
//
// Vocabulary. A snapshot is one file for one time. Its *groups* sit at the root ("Header",
// "Units", "PartType0", ...); a group holds *attributes* (numbers as 1-D arrays, even single ones,
// as GADGET and SWIFT write them; text as a scalar string) and *datasets*. A dataset holds one
// quantity of every particle of its group: N values, or N x C for a vector quantity (C columns,
// e.g. 3 coordinates); rank r's rows follow those of ranks 0..r-1. The file is written as
// `<path>.partial` and renamed to `<path>` by close() (or finish() then commit()): a crash never
// leaves a half-written file under the final name nor harms an earlier file of that name, and a
// writer destroyed before close() removes its partial file. Paths that exist and are not regular
// files are refused before anything is written.
//
//   snapshot_writer out("run_0003.hdf5");
//   out.set_attributes("Header", {{"Time", std::vector<double>{t}}, {"Dimension", std::vector<std::int32_t>{2}}});
//   out.write("PartType0", "Coordinates", xyz.data(), owned, 3, {{"Description", "positions"s}});
//   out.close();
//
// Every member function is collective over the writer's communicator, with the same groups,
// names and attribute values on every rank in the same order. Errors throw the same io_error on
// every rank (collective_agreement.hh).
#pragma once

#include "flecsi_lite/io/detail/hdf5_handle.hh"
#include "flecsi_lite/io/detail/partial_file.hh"
#include "flecsi_lite/io/element_type.hh"
#include "flecsi_lite/runtime/context.hh"

#include <mpi.h>

#include <cstddef>
#include <cstdint>
#include <set>
#include <string>
#include <variant>
#include <vector>

namespace flecsi_lite::io {

/// An attribute of a snapshot: a 1-D array of numbers of one type, or a string.
using snapshot_attribute_value =
  std::variant<std::vector<std::int32_t>, std::vector<std::uint32_t>, std::vector<std::int64_t>, std::vector<float>,
               std::vector<double>, std::string>;

struct snapshot_attribute {
  std::string name;
  snapshot_attribute_value value;
};
using snapshot_attributes = std::vector<snapshot_attribute>;

class snapshot_writer {
 public:
  explicit snapshot_writer(std::string path, MPI_Comm comm = runtime::communicator());
  snapshot_writer(const snapshot_writer&) = delete;
  snapshot_writer& operator=(const snapshot_writer&) = delete;
  /// Without close(): closes the partial file (emptied first when a write failed) and removes
  /// it; `path` stays as it was.
  ~snapshot_writer();

  /// Adds `attributes` to group `group` (created when absent; "" is the root), replacing any of
  /// the same name.
  void set_attributes(const std::string& group, const snapshot_attributes& attributes);

  /// Writes this rank's `local_rows` rows of `columns` values each (row-major) as dataset `name`
  /// of group `group` (created when absent): shape N (columns 1) or N x columns, with
  /// `attributes` on the dataset. A dataset is written once.
  template<class T>
  void write(const std::string& group, const std::string& name, const T* data, std::size_t local_rows, int columns = 1,
             const snapshot_attributes& attributes = {}) {
    write_array(group, name, element_type_of<T>(), data, local_rows, columns, attributes);
  }
  /// Same, for a contiguous container holding local rows x columns values.
  template<class Container>
  void write(const std::string& group, const std::string& name, const Container& values, int columns = 1,
             const snapshot_attributes& attributes = {}) {
    const auto size = static_cast<std::size_t>(values.size());
    write(group, name, values.data(), columns > 0 ? size / static_cast<std::size_t>(columns) : 0, columns, attributes);
  }

  /// finish() then commit().
  void close();
  /// Flushes and closes `<path>.partial`, complete; `path` is not touched yet.
  void finish();
  /// After finish(): renames `<path>.partial` to `<path>` (refused when `path` has become
  /// something else than a regular file).
  void commit();

  bool is_open() const { return output_.is_open(); }
  const std::string& path() const { return path_; }
  std::string partial_path() const { return output_.partial_path(); }

 private:
  void write_array(const std::string& group, const std::string& name, element_type type, const void* data,
                   std::size_t local_rows, int columns, const snapshot_attributes& attributes);
  void require_open(const char* operation) const;
  hdf5_handle open_group(const std::string& group);  // inside agree()
  void abandon() noexcept;

  std::string path_;
  MPI_Comm comm_;
  partial_file output_;             // the file under its temporary name, finished, committed
  std::set<std::string> datasets_;  // "group/name" of the datasets written
};

}  // namespace flecsi_lite::io
