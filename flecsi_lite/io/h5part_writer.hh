// Collective writer of H5Part files with parallel HDF5 (MPI-IO, collective transfers): per step a
// group Step#k with one 1-D dataset per quantity, each rank writing its contiguous slice.
//
// Vocabulary. A *step* is one group Step#k, k = 0, 1, ... in writing order; its attributes
// TimeValue and time hold the simulation time, step the iteration number, dt the time step. A
// *dataset* is one quantity of every particle of the step (global length N, the sum of the
// ranks' local counts); rank r's particles follow those of ranks 0..r-1. The file is written as
// `<path>.partial` and renamed to `<path>` by close() (or finish() then commit()): a crash never
// leaves a half-written file under the final name nor harms an older complete file of that name;
// every finished step is flushed, so the partial file holds all of them. A path that exists and is
// not a regular file (device, folder, symbolic link, fifo) is refused before anything is written.
// After a failed write (a full disk), HDF5 is still closed completely.
//
//   h5part_writer out("sod.h5part");
//   out.set_attribute("program", "sod");
//   out.begin_step({time, iteration, dt});
//   out.write("x", x.data(), owned);      // every rank, same names in the same order
//   out.write("rho", rho);                // any container with data() and size()
//   out.end_step();
//   out.close();
//
// Every member function is collective over the writer's communicator. Errors throw the same
// io_error on every rank.
#pragma once

#include "flecsi_lite/io/attribute_value.hh"
#include "flecsi_lite/io/detail/hdf5_handle.hh"
#include "flecsi_lite/io/detail/partial_file.hh"
#include "flecsi_lite/io/element_type.hh"
#include "flecsi_lite/io/step_info.hh"
#include "flecsi_lite/runtime/context.hh"

#include <mpi.h>

#include <cstddef>
#include <cstdint>
#include <optional>
#include <set>
#include <string>

namespace flecsi_lite::io {

/// Root attributes that describe a run (program, resolved parameters, dimension).
struct run_description {
  std::string program;
  std::string parameters;  // the resolved parameter set, as text
  int dimension = 3;
};

class h5part_writer {
 public:
  enum class mode {
    create,  // a new series: the partial file starts empty
    append   // continue the complete file `path` (a copy of it), or the `<path>.partial` an
             // interrupted run left when `path` is absent, or create it when both are absent
  };

  explicit h5part_writer(std::string path, MPI_Comm comm = runtime::communicator(), mode how = mode::create);
  h5part_writer(const h5part_writer&) = delete;
  h5part_writer& operator=(const h5part_writer&) = delete;
  /// Without close(): drops an unfinished step, closes the partial file (collectively, like
  /// every parallel HDF5 close; emptied and removed when it cannot be flushed) and leaves the
  /// final name untouched.
  ~h5part_writer();

  /// Root attribute, replaced if present; same value on every rank.
  void set_attribute(const std::string& name, const attribute_value& value);
  /// The attributes program, parameters and dimension.
  void describe_run(const run_description& run);

  /// Opens Step#<steps_written()> with attributes TimeValue = time = info.time, step, dt.
  void begin_step(const step_info& info);
  /// Writes this rank's `local_count` values of quantity `name` into the current step. Every
  /// dataset of a step has the same global length.
  template<class T>
  void write(const std::string& name, const T* data, std::size_t local_count) {
    write_array(name, element_type_of<T>(), data, local_count);
  }
  /// Same, for a contiguous container (std::vector, host Kokkos::View, ...).
  template<class Container>
  void write(const std::string& name, const Container& values) {
    write(name, values.data(), static_cast<std::size_t>(values.size()));
  }
  /// Appending (no open step): unlinks the last steps while their `step` attribute (the
  /// iteration) is >= `first_dropped`, so that a restart at iteration N continues the series
  /// after what the run it continues wrote up to N; updates NumSteps. Returns the steps dropped.
  std::int64_t drop_steps_from(std::int64_t first_dropped);
  /// The `step` attribute of the last step written (or found when appending); -1 without steps.
  std::int64_t last_iteration() const { return last_iteration_; }
  /// An extra attribute of the current step.
  void set_step_attribute(const std::string& name, const attribute_value& value);
  /// Closes the step, updates NumSteps and flushes the file.
  void end_step();

  /// Ends an open step, closes the file and renames `<path>.partial` to `<path>`: finish(), commit().
  void close();
  /// Ends an open step and closes `<path>.partial`, complete; `<path>` is not touched yet (a run
  /// checks its results before it replaces an earlier output).
  void finish();
  /// After finish(): renames `<path>.partial` to `<path>` (refused when `<path>` has become
  /// something else than a regular file). Without it, the destructor leaves both files as they are.
  void commit();

  bool is_open() const { return output_.is_open(); }
  /// Finished and not yet committed.
  bool awaits_commit() const { return output_.awaits_commit(); }
  bool in_step() const { return step_group_.valid(); }
  std::int64_t steps_written() const { return steps_written_; }
  const std::string& path() const { return path_; }
  std::string partial_path() const { return output_.partial_path(); }

 private:
  void write_array(const std::string& name, element_type type, const void* data, std::size_t local_count);
  void require_open(const char* operation) const;
  std::int64_t iteration_of(std::int64_t step) const;  // inside agree()
  void abandon() noexcept;

  std::string path_;
  MPI_Comm comm_;
  partial_file output_;  // the file under its temporary name, finished, committed
  hdf5_handle step_group_;
  std::int64_t steps_written_ = 0;
  std::int64_t last_iteration_ = -1;
  std::set<std::string> step_datasets_;       // names written in the open step
  std::optional<std::uint64_t> step_length_;  // global length of the open step's datasets
};

}  // namespace flecsi_lite::io
