// The errors of the I/O layer: one std::runtime_error subclass per kind of failure, each message
// naming the file, the step and the dataset concerned, thrown identically on every rank.
#pragma once

#include <stdexcept>
#include <string>

namespace flecsi_lite::io {

/// What went wrong; travels between ranks so that every rank throws the same subclass.
enum class failure {
  file,       // missing, unreadable, not HDF5, truncated or corrupted, cannot be created or renamed
  step,       // no such step in the file
  dataset,    // no such dataset in the step
  attribute,  // no such attribute
  layout,     // the file or the calls break the H5Part layout (lengths differ, ranks disagree)
  type,       // element type of a dataset or attribute differs from the one asked for
  slice,      // a requested slice lies outside the dataset
  usage,      // API misuse: write outside a step, a dataset written twice, a closed writer
  system      // anything else (out of memory, an unexpected HDF5 failure)
};

class io_error : public std::runtime_error {
 public:
  io_error(failure kind, const std::string& message) : std::runtime_error(message), kind_(kind) {}
  failure kind() const { return kind_; }

 private:
  failure kind_;
};

struct file_error : io_error {
  explicit file_error(const std::string& m) : io_error(failure::file, m) {}
};
struct missing_step_error : io_error {
  explicit missing_step_error(const std::string& m) : io_error(failure::step, m) {}
};
struct missing_dataset_error : io_error {
  explicit missing_dataset_error(const std::string& m) : io_error(failure::dataset, m) {}
};
struct missing_attribute_error : io_error {
  explicit missing_attribute_error(const std::string& m) : io_error(failure::attribute, m) {}
};
struct layout_error : io_error {
  explicit layout_error(const std::string& m) : io_error(failure::layout, m) {}
};
struct element_type_error : io_error {
  explicit element_type_error(const std::string& m) : io_error(failure::type, m) {}
};
struct slice_error : io_error {
  explicit slice_error(const std::string& m) : io_error(failure::slice, m) {}
};
struct usage_error : io_error {
  explicit usage_error(const std::string& m) : io_error(failure::usage, m) {}
};

/// Throws the subclass that corresponds to `kind`.
[[noreturn]] inline void throw_io_error(failure kind, const std::string& message) {
  switch (kind) {
    case failure::file:
      throw file_error(message);
    case failure::step:
      throw missing_step_error(message);
    case failure::dataset:
      throw missing_dataset_error(message);
    case failure::attribute:
      throw missing_attribute_error(message);
    case failure::layout:
      throw layout_error(message);
    case failure::type:
      throw element_type_error(message);
    case failure::slice:
      throw slice_error(message);
    case failure::usage:
      throw usage_error(message);
    case failure::system:
      break;
  }
  throw io_error(failure::system, message);
}

}  // namespace flecsi_lite::io
