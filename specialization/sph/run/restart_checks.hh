// What a restart reads, checked for consistency before it is used (issue 38, item 3): a value no
// run can have written (a step window beyond the timeline, a NaN bin, a dt longer than what is
// left of the run) would otherwise change the result silently. Each check names the file, the
// dataset or attribute and, for per-particle values, the particle id; a failure is a layout_error
// (exit status 3, a bad file), thrown on every rank alike.
#pragma once

#include "specialization/sph/model/timeline.hh"

#include "flecsi_lite/io.hh"

#include <mpi.h>

#include <algorithm>
#include <cstdint>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace flecsph::sph::detail {

/// Collective. Individual time steps: for every fluid particle of this rank's block of Step#0 of
/// the checkpoint `in`, time_bin (an integer dataset) is a bin in [0, timeline::bins]; its step
/// began at or before the timeline's now and ends after it, within the span, on a multiple of
/// 2^time_bin (where every step of that bin ends); over all ranks, the earliest end of a fluid
/// particle's step is the timeline's next (what choose_time_bins set when the checkpoint was
/// written).
inline void check_time_bins(const flecsi_lite::io::h5part_reader& in, const timeline& clock) {
  namespace io = flecsi_lite::io;
  const std::string where = "checkpoint '" + in.path() + "' Step#0";
  for (const char* name : {"time_bin", "step_begin", "step_end"}) {
    if (!in.has_dataset(0, name))
      throw io::layout_error(where + " has no dataset '" + name + "', which individual time steps need");
    const auto type = in.dataset_type(0, name);
    if (type != io::element_type::int32 && type != io::element_type::int64 && type != io::element_type::uint64)
      throw io::layout_error(where + " dataset '" + name + "' holds " + io::element_type_name(type) +
                             " values: it must hold integers");
  }
  const auto block = in.block(0);
  // Every integer type as int64 (a uint64 beyond 2^63 wraps to a negative value: refused alike).
  const auto integers = [&](const char* name) {
    std::vector<std::int64_t> values;
    switch (in.dataset_type(0, name)) {
      case io::element_type::int32:
        for (const std::int32_t v : in.read<std::int32_t>(0, name, block)) values.push_back(v);
        break;
      case io::element_type::uint64:
        for (const std::uint64_t v : in.read<std::uint64_t>(0, name, block))
          values.push_back(static_cast<std::int64_t>(v));
        break;
      default:
        values = in.read<std::int64_t>(0, name, block);
    }
    return values;
  };
  const auto bins = integers("time_bin");
  const auto begins = integers("step_begin");
  const auto ends = integers("step_end");
  const auto ids = in.read<std::uint64_t>(0, "id", block);
  std::vector<std::int64_t> kinds;
  if (in.has_dataset(0, "kind") && in.dataset_type(0, "kind") != io::element_type::float64 &&
      in.dataset_type(0, "kind") != io::element_type::float32)
    kinds = integers("kind");
  std::optional<io::failure_record> failed;
  std::int64_t earliest = timeline::span;
  for (std::size_t a = 0; a < ids.size() && !failed; ++a) {
    if (!kinds.empty() && kinds[a] != 0) continue;  // walls are active in every step: no window
    // (A woken particle's step may be longer than its new bin's: its window is not checked by length.)
    const std::int64_t bin = bins[a], begin = begins[a], end = ends[a];
    std::ostringstream problem;
    if (bin < 0 || bin > timeline::bins)
      problem << "dataset 'time_bin' = " << bin << " is not a bin in [0, " << timeline::bins << "]";
    else if (begin > clock.now)
      problem << "dataset 'step_begin' = " << begin << " is after the timeline's now = " << clock.now;
    else if (end <= clock.now || end > timeline::span)
      problem << "dataset 'step_end' = " << end << " is not after the timeline's now = " << clock.now
              << " and within its span 2^" << timeline::bins;
    else if (end % timeline::ticks_of(static_cast<int>(bin)) != 0)
      problem << "dataset 'step_end' = " << end << " is not a multiple of 2^time_bin = 2^" << bin
              << ", where the steps of that bin end";
    if (!problem.str().empty())
      failed = io::failure_record{io::failure::layout,
                                  where + ": " + problem.str() + " for the particle with id " + std::to_string(ids[a])};
    earliest = std::min(earliest, end);
  }
  io::raise_if_any(in.communicator(), failed);
  MPI_Allreduce(MPI_IN_PLACE, &earliest, 1, MPI_INT64_T, MPI_MIN, in.communicator());
  if (earliest != clock.next)
    throw io::layout_error(where + ": the earliest 'step_end' of a fluid particle is " + std::to_string(earliest) +
                           ", the run state 'timeline_next' is " + std::to_string(clock.next) +
                           ": the next step would not be the one the writing run took");
}

/// The clock of an individual-step checkpoint against its timeline: the attribute 'time' is the
/// time of tick now, and 'dt' the length of the step from now to next (as choose_time_bins set
/// them). Throws layout_error naming the file and the attribute.
inline void check_clock_on_timeline(const std::string& path, const timeline& clock, double time, double dt,
                                    double end_time) {
  std::ostringstream m;
  m.precision(17);
  if (time != clock.time_at(clock.now, end_time))
    m << "checkpoint '" << path << "' Step#0: attribute 'time' = " << time
      << " is not the time of the timeline's now = " << clock.now << " (t = " << clock.time_at(clock.now, end_time)
      << ")";
  else if (dt != clock.duration(clock.next - clock.now))
    m << "checkpoint '" << path << "' Step#0: attribute 'dt' = " << dt
      << " is not the step from the timeline's now = " << clock.now << " to next = " << clock.next << " ("
      << clock.duration(clock.next - clock.now) << ")";
  if (!m.str().empty()) throw flecsi_lite::io::layout_error(m.str());
}

/// Global time steps: the checkpoint's 'dt', the step about to be taken, was at most what was left
/// of the writing run (its end_time, `written_end_time`, from the parameters it stores): dt =
/// min(criteria, end_time - time). Throws layout_error naming the file and the attribute.
inline void check_step_left(const std::string& path, double time, double dt, double written_end_time) {
  if (dt <= written_end_time - time) return;
  std::ostringstream m;
  m.precision(17);
  m << "checkpoint '" << path << "' Step#0: attribute 'dt' = " << dt << " is longer than what was left of the run "
    << "that wrote it (end_time " << written_end_time << " - time " << time << " = " << written_end_time - time
    << "): no run takes such a step";
  throw flecsi_lite::io::layout_error(m.str());
}

}  // namespace flecsph::sph::detail
