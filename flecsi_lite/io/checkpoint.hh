// Checkpoints for restarts: one complete H5Part step (Step#0) of full-precision arrays plus the
// run's state as root attributes, written under a temporary name and renamed when complete, so
// that the previous checkpoint of that name survives any failure while the new one is written.
// The clock (Step#0's time, step, dt) and the run state carry checksums (run_state_checksums.hh)
// that a restart verifies.
#pragma once

#include "flecsi_lite/io/attribute_value.hh"
#include "flecsi_lite/io/h5part_reader.hh"
#include "flecsi_lite/io/h5part_writer.hh"
#include "flecsi_lite/io/step_info.hh"
#include "flecsi_lite/runtime/context.hh"

#include <cstddef>
#include <cstdint>
#include <functional>
#include <map>
#include <optional>
#include <string>

namespace flecsi_lite::io {

/// What a restart needs besides the particle arrays (counters, next output time, ...).
using run_state = std::map<std::string, attribute_value>;

/// Root attribute "checkpoint" = 1 marks a checkpoint; state entry "n" is root attribute "state:n".
inline constexpr const char* checkpoint_marker = "checkpoint";
inline constexpr const char* checkpoint_state_prefix = "state:";

/// Collective. Writes `path`: Step#0 with time/step/dt from `info` and the arrays that
/// `write_arrays` writes (in their own type: doubles stay doubles), `state` and the checksums of
/// the clock and `state` (root attribute "checksums"). An exception
/// from `write_arrays` (on every rank) leaves the previous file of that name untouched.
void write_checkpoint(const std::string& path, const step_info& info, const run_state& state,
                      const std::function<void(h5part_writer&)>& write_arrays, MPI_Comm comm = runtime::communicator());

struct checkpoint_contents {
  step_info info;
  run_state state;
};

/// Collective. The time and run state of a checkpoint; read its arrays with reader.read<T>(0, name).
/// Throws file_error when the file is not a checkpoint.
checkpoint_contents read_checkpoint(const h5part_reader& reader);

/// Collective. Throws layout_error naming the file and every value of the clock (Step#0's
/// attributes time, step, dt as the file holds them) or of the run state whose checksum differs
/// from the one written, or saying that the file has no checksums (a checkpoint written before
/// they existed: its run state cannot be verified, the run must be made again).
void verify_run_state(const h5part_reader& reader, const checkpoint_contents& contents);

/// Collective: an id that more than one of the `count` ids of all ranks share (the smallest), or
/// none. Each id goes to rank id mod size, which sorts what it received: O(N / ranks) memory.
std::optional<std::uint64_t> duplicate_id(const std::uint64_t* ids, std::size_t count,
                                          MPI_Comm comm = runtime::communicator());

}  // namespace flecsi_lite::io
