// Per-particle columns a rank reads its block of, whatever file holds them: one step of an H5Part
// file (h5part_step_columns) or the particle group of a GADGET/SWIFT-layout file
// (gadget_reader.hh). The field reader (data/field_io.hh) reads initial data and checkpoints
// through it, so every format is checked by the same fields' rules.
//
// Vocabulary: a column is one named component of the particles (x, vx, m, ...); the block is this
// rank's balanced part of the particles (block_slice), the seed's "read f in parallel".
// Every member function is collective over communicator() and throws the same io_error on every
// rank, naming the file and the dataset.
#pragma once

#include "flecsi_lite/io/element_type.hh"
#include "flecsi_lite/io/particle_partition.hh"

#include <mpi.h>

#include <cstdint>
#include <string>
#include <vector>

namespace flecsi_lite::io {

class h5part_reader;

class column_source {
 public:
  virtual ~column_source() = default;
  /// The file and the place in it, for messages ("'a.h5part' Step#3").
  virtual std::string where() const = 0;
  virtual MPI_Comm communicator() const = 0;
  /// This rank's block of the particles.
  virtual slice block() const = 0;
  virtual bool has_column(const std::string& name) const = 0;
  /// The element type of the file's values of `name`; missing_dataset_error when absent.
  virtual element_type column_type(const std::string& name) const = 0;
  /// This rank's block of column `name`; T must be its element type.
  template<class T>
  std::vector<T> read(const std::string& name) const {
    std::vector<T> values(block().count);
    read_column(name, block(), element_type_of<T>(), values.data());
    return values;
  }

 protected:
  virtual void read_column(const std::string& name, slice part, element_type type, void* out) const = 0;
};

/// Step `step` of an H5Part file: its datasets are the columns.
class h5part_step_columns final : public column_source {
 public:
  h5part_step_columns(const h5part_reader& in, std::int64_t step) : in_(in), step_(step) {}
  std::string where() const override;
  MPI_Comm communicator() const override;
  slice block() const override;
  bool has_column(const std::string& name) const override;
  element_type column_type(const std::string& name) const override;

 protected:
  void read_column(const std::string& name, slice part, element_type type, void* out) const override;

 private:
  const h5part_reader& in_;
  std::int64_t step_;
};

}  // namespace flecsi_lite::io
