// Where an SPH run stops before end_time (app.hh): max_steps, wall_time_limit or the stop file,
// one verdict for every rank.
#pragma once

#include "specialization/sph/run/app_state.hh"

#include <string>

namespace flecsph::sph {
namespace detail {
/// After the clock: a run that max_steps stopped before end_time, or whose wall_time_limit or
/// stop_file says so (one verdict for every rank), finishes at this step with a stop reason.
template<int D>
void check_run_limits(app_state<D>& s) {
  if (s.finished) {
    if (s.time < s.run.end_time && s.stop_reason.empty())
      s.stop_reason = "max_steps = " + std::to_string(s.run.max_steps) + " reached";
    return;
  }
  s.stop_reason = s.stop.check();
  s.finished = !s.stop_reason.empty();
}
}  // namespace detail
}  // namespace flecsph::sph
