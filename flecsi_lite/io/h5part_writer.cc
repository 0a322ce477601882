// Collective H5Part writer over parallel HDF5 (see h5part_writer.hh).
#include "flecsi_lite/io/h5part_writer.hh"

#include "flecsi_lite/io/collective_agreement.hh"
#include "flecsi_lite/io/detail/h5part_layout.hh"
#include "flecsi_lite/io/detail/h5part_steps.hh"
#include "flecsi_lite/io/detail/hdf5_attributes.hh"
#include "flecsi_lite/io/detail/hdf5_errors.hh"
#include "flecsi_lite/io/detail/hdf5_parallel.hh"
#include "flecsi_lite/io/detail/partial_file.hh"
#include "flecsi_lite/io/detail/rank_slice.hh"
#include "flecsi_lite/io/output_path.hh"
#include "flecsi_lite/io/particle_partition.hh"
#include "flecsi_lite/runtime/log.hh"

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <utility>

namespace flecsi_lite::io {

namespace {
// Exact text of a value, for checking that every rank passes the same one.
std::string fingerprint(const std::string& name, const attribute_value& value) {
  char real[40] = "";
  if (auto* d = std::get_if<double>(&value)) std::snprintf(real, sizeof real, "%a", *d);
  return name + '\0' + std::to_string(value.index()) + '\0' + (*real ? real : to_string(value));
}
}  // namespace

h5part_writer::h5part_writer(std::string path, MPI_Comm comm, mode how)
    : path_(std::move(path)), comm_(comm), output_(path_, comm) {
  hdf5_quiet_scope quiet;
  // Before anything is written: the final name and the temporary one must be absent or regular
  // files, or the rename would replace a device, a folder or a link (and H5Fcreate follow it).
  agree(comm_, [&] {
    if (rank_of(comm_) != 0) return;
    require_replaceable(path_);
    require_replaceable(partial_path(), "temporary file");
  });
  // Appending works on a copy, so that the complete file stays intact until close().
  int append_to_copy = 0;
  if (how == mode::append) {
    agree(comm_, [&] {
      if (rank_of(comm_) != 0) return;
      // A run stopped hard (killed) left its flushed steps only in the partial file: continue it.
      if (!std::filesystem::exists(path_)) {
        append_to_copy = std::filesystem::is_regular_file(partial_path());
        return;
      }
      std::error_code error;
      std::filesystem::copy_file(path_, partial_path(), std::filesystem::copy_options::overwrite_existing, error);
      if (error)
        throw file_error("cannot copy '" + path_ + "' to '" + partial_path() + "' to append to it: " + error.message());
      append_to_copy = 1;
    });
    MPI_Bcast(&append_to_copy, 1, MPI_INT, 0, comm_);
  }

  // The same name and working folder on every rank: the same verdict everywhere.
  const std::string name = mpi_io_name(partial_path());
  auto access = mpio_file_access(comm_);
  // No modification time on the root group either: identical runs write identical files.
  auto creation = property_list_handle(H5Pcreate(H5P_FILE_CREATE));
  if (!creation || H5Pset_obj_track_times(creation.get(), false) < 0)
    throw io_error(failure::system, "cannot describe '" + partial_path() + "'" + hdf5_reason());
  const hid_t id = append_to_copy ? H5Fopen(name.c_str(), H5F_ACC_RDWR, access.get())
                                  : H5Fcreate(name.c_str(), H5F_ACC_TRUNC, creation.get(), access.get());
  std::optional<failure_record> failed;
  if (id < 0)
    failed = failure_record{failure::file, "cannot " + std::string(append_to_copy ? "open" : "create") + " '" +
                                             partial_path() + "' for writing" + hdf5_reason() +
                                             (append_to_copy ? " (to continue the series in it; remove it or "
                                                               "choose another output file)"
                                                             : "")};
  output_.file() = file_handle(id);
  try {
    raise_if_any(comm_, failed);
  } catch (...) {
    output_.file().release();  // a parallel close on only the ranks that opened it would never return
    throw;
  }

  if (append_to_copy) {
    agree(comm_, [&] {
      const auto steps = h5part::step_indices(output_.file().get());
      for (std::size_t k = 0; k < steps.size(); ++k)
        if (steps[k] != static_cast<std::int64_t>(k))
          throw layout_error("cannot append to '" + path_ + "': its steps are not Step#0 to Step#" +
                             std::to_string(steps.size() - 1));
      steps_written_ = static_cast<std::int64_t>(steps.size());
      last_iteration_ = steps_written_ > 0 ? iteration_of(steps_written_ - 1) : -1;
    });
  }
}

h5part_writer::~h5part_writer() { abandon(); }

void h5part_writer::abandon() noexcept {
  if (output_.awaits_commit()) {
    if (rank_of(comm_) == 0)
      log::warn() << "h5part: '" << path_ << "' was left unchanged (the run did not pass its checks); "
                  << "its complete output of " << steps_written_ << " steps is in '" << partial_path() << "'";
    return;
  }
  if (!is_open()) return;
  try {
    hdf5_quiet_scope quiet;
    if (!output_.storage_failed() && in_step()) {
      // An unfinished step would look complete to a reader: unlink it.
      step_group_.close();
      H5Ldelete(output_.file().get(), h5part::step_group_name(steps_written_).c_str(), H5P_DEFAULT);
    }
    step_group_.close();
    // The finished steps stay in the partial file when it could be flushed (partial_file.hh).
    const bool flushed = output_.close_unfinished();
    if (rank_of(comm_) != 0) return;
    if (flushed) {
      log::warn() << "h5part: '" << path_ << "' was not closed; its " << steps_written_ << " finished steps are in '"
                  << partial_path() << "'";
    } else {
      std::error_code error;
      std::filesystem::remove(partial_path(), error);
      log::warn() << "h5part: '" << path_ << "' was not closed and its temporary file could not be "
                  << "completed (disk full?): '" << partial_path() << "' removed, '" << path_ << "' unchanged";
    }
  } catch (...) {}
}

void h5part_writer::require_open(const char* operation) const {
  if (!is_open()) throw usage_error(std::string(operation) + ": the H5Part writer of '" + path_ + "' is closed");
}

void h5part_writer::set_attribute(const std::string& name, const attribute_value& value) {
  hdf5_quiet_scope quiet;
  if (!same_on_all_ranks(comm_, fingerprint(name, value)))
    throw layout_error("ranks set different root attributes (or values) at the same point in '" + path_ + "'");
  agree(comm_, [&] {
    require_open("set_attribute");
    write_attribute(output_.file().get(), name, value);
  });
}

void h5part_writer::describe_run(const run_description& run) {
  set_attribute(h5part::attribute::program, run.program);
  set_attribute(h5part::attribute::parameters, run.parameters);
  set_attribute(h5part::attribute::dimension, std::int64_t{run.dimension});
}

std::int64_t h5part_writer::iteration_of(std::int64_t step) const {
  const std::string name = h5part::step_group_name(step);
  auto group = group_handle(H5Gopen2(output_.file().get(), name.c_str(), H5P_DEFAULT));
  if (!group) throw io_error(failure::file, "cannot open " + name + " of '" + partial_path() + "'" + hdf5_reason());
  if (!has_attribute(group.get(), h5part::attribute::step)) return step;
  const std::string what = "attribute 'step' of " + name + " in '" + path_ + "'";
  return attribute_as<std::int64_t>(read_attribute(group.get(), h5part::attribute::step, what), what);
}

std::int64_t h5part_writer::drop_steps_from(std::int64_t first_dropped) {
  hdf5_quiet_scope quiet;
  std::int64_t dropped = 0;
  agree(comm_, [&] {
    require_open("drop_steps_from");
    if (in_step())
      throw usage_error("drop_steps_from: step " + std::to_string(steps_written_) + " of '" + path_ + "' is open");
    // Every rank unlinks the same groups: a metadata change, collective in parallel HDF5.
    while (steps_written_ > 0 && iteration_of(steps_written_ - 1) >= first_dropped) {
      const std::string name = h5part::step_group_name(steps_written_ - 1);
      if (H5Ldelete(output_.file().get(), name.c_str(), H5P_DEFAULT) < 0)
        throw io_error(failure::system, "cannot remove " + name + " from '" + partial_path() + "'" + hdf5_reason());
      --steps_written_;
      ++dropped;
    }
    last_iteration_ = steps_written_ > 0 ? iteration_of(steps_written_ - 1) : -1;
    if (dropped) write_attribute(output_.file().get(), h5part::attribute::num_steps, std::int64_t{steps_written_});
  });
  return dropped;
}

void h5part_writer::begin_step(const step_info& info) {
  hdf5_quiet_scope quiet;
  char text[96];
  std::snprintf(text, sizeof text, "%a %lld %a", info.time, static_cast<long long>(info.step), info.dt);
  if (!same_on_all_ranks(comm_, text))
    throw layout_error("ranks begin a step of '" + path_ + "' with different time, step or dt");
  hdf5_handle group;
  agree(comm_, [&] {
    require_open("begin_step");
    if (in_step())
      throw usage_error("begin_step: step " + std::to_string(steps_written_) + " of '" + path_ +
                        "' is still open; call end_step first");
    const std::string name = h5part::step_group_name(steps_written_);
    // No modification times: identical runs write identical files.
    auto creation = property_list_handle(H5Pcreate(H5P_GROUP_CREATE));
    if (!creation || H5Pset_obj_track_times(creation.get(), false) < 0)
      throw io_error(failure::system, "cannot describe group " + name + hdf5_reason());
    group = group_handle(H5Gcreate2(output_.file().get(), name.c_str(), H5P_DEFAULT, creation.get(), H5P_DEFAULT));
    if (!group)
      throw io_error(failure::system, "cannot create group " + name + " in '" + partial_path() + "'" + hdf5_reason());
    write_attribute(group.get(), h5part::attribute::time_value, info.time);
    write_attribute(group.get(), h5part::attribute::time, info.time);
    write_attribute(group.get(), h5part::attribute::step, info.step);
    write_attribute(group.get(), h5part::attribute::dt, info.dt);
  });
  step_group_ = std::move(group);
  last_iteration_ = info.step;
  step_datasets_.clear();
  step_length_.reset();
}

void h5part_writer::set_step_attribute(const std::string& name, const attribute_value& value) {
  hdf5_quiet_scope quiet;
  if (!same_on_all_ranks(comm_, fingerprint(name, value)))
    throw layout_error("ranks set different step attributes (or values) at the same point in '" + path_ + "'");
  agree(comm_, [&] {
    require_open("set_step_attribute");
    if (!in_step()) throw usage_error("set_step_attribute '" + name + "': no open step in '" + path_ + "'");
    write_attribute(step_group_.get(), name, value);
  });
}

void h5part_writer::write_array(const std::string& name, element_type type, const void* data, std::size_t local_count) {
  hdf5_quiet_scope quiet;
  const std::string step = "step " + std::to_string(steps_written_);
  const std::string where = "dataset '" + name + "' of " + step + " in '" + path_ + "'";
  agree(comm_, [&] {
    require_open("write");
    if (!in_step()) throw usage_error("write " + where + ": no open step; call begin_step first");
    if (name.empty() || name == "." || name.find('/') != std::string::npos)
      throw usage_error("write: '" + name + "' is not a valid dataset name (in " + step + " of '" + path_ + "')");
    if (step_datasets_.count(name)) throw usage_error("write: " + where + " is already written");
    if (local_count > 0 && data == nullptr) throw usage_error("write " + where + ": no data");
  });
  if (!same_on_all_ranks(comm_, name + '\0' + element_type_name(type)))
    throw layout_error(
      "ranks write different datasets (names or element types differ) at the "
      "same point of " +
      step + " in '" + path_ + "'");
  const placement place = place_contiguously(comm_, local_count);
  if (step_length_ && *step_length_ != place.global_length)
    throw layout_error(where + " has " + std::to_string(place.global_length) +
                       " particles but the step's other datasets have " + std::to_string(*step_length_));

  hdf5_handle dataset, file_space, memory_space;
  agree(comm_, [&] {
    const hsize_t global = place.global_length;
    auto global_space = dataspace_handle(H5Screate_simple(1, &global, nullptr));
    auto creation = property_list_handle(H5Pcreate(H5P_DATASET_CREATE));
    // Every element is written below: no fill value needed. No modification times: identical
    // runs write identical files.
    if (!global_space || !creation || H5Pset_fill_time(creation.get(), H5D_FILL_TIME_NEVER) < 0 ||
        H5Pset_obj_track_times(creation.get(), false) < 0)
      throw io_error(failure::system, "cannot describe " + where + hdf5_reason());
    dataset = dataset_handle(H5Dcreate2(step_group_.get(), name.c_str(), file_type(type), global_space.get(),
                                        H5P_DEFAULT, creation.get(), H5P_DEFAULT));
    if (!dataset) throw io_error(failure::system, "cannot create " + where + hdf5_reason());
    auto slice = select_rank_slice(dataset.get(), place.local.offset, place.local.count, 0, 1, 1, where);
    file_space = std::move(slice.file_space);
    memory_space = std::move(slice.memory_space);
  });

  // Collective: every rank takes part, those without particles with an empty selection. A
  // dataset without any element has no storage to write to (the same on every rank).
  auto transfer = collective_transfer();
  const char nothing = 0;
  std::optional<failure_record> failed;
  if (place.global_length > 0 && H5Dwrite(dataset.get(), memory_type(type), memory_space.get(), file_space.get(),
                                          transfer.get(), local_count > 0 ? data : &nothing) < 0)
    failed = failure_record{failure::system, "cannot write " + where + hdf5_reason()};
  output_.raise_marking_storage_failure(failed);
  step_datasets_.insert(name);
  step_length_ = place.global_length;
}

void h5part_writer::end_step() {
  hdf5_quiet_scope quiet;
  agree(comm_, [&] {
    require_open("end_step");
    if (!in_step()) throw usage_error("end_step: no open step in '" + path_ + "'");
    if (step_group_.close() < 0)
      throw io_error(failure::system,
                     "cannot close step " + std::to_string(steps_written_) + " of '" + path_ + "'" + hdf5_reason());
    write_attribute(output_.file().get(), h5part::attribute::num_steps, std::int64_t{steps_written_ + 1});
  });
  ++steps_written_;
  step_datasets_.clear();
  step_length_.reset();
  // The partial file now holds every finished step, should the run stop here.
  std::optional<failure_record> failed;
  if (H5Fflush(output_.file().get(), H5F_SCOPE_GLOBAL) < 0)
    failed = failure_record{failure::system, "cannot flush '" + partial_path() + "'" + hdf5_reason()};
  output_.raise_marking_storage_failure(failed);
}

void h5part_writer::finish() {
  if (!is_open()) return;
  if (in_step()) end_step();
  output_.finish();  // a failed flush leaves the file open for abandon()
}

void h5part_writer::commit() {
  // Only now, with every byte written by every rank, does the file take its final name.
  output_.commit();
}

void h5part_writer::close() {
  finish();
  commit();
}

}  // namespace flecsi_lite::io
