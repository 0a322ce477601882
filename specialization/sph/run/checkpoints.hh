// The checkpoints of an SPH run (app.hh, restart.hh): one every checkpoint_every steps, and one
// when the run stops before end_time, printed with the command that resumes it.
#pragma once

#include "specialization/sph/run/app_state.hh"
#include "specialization/sph/run/restart.hh"

#include "flecsi_lite/runtime.hh"

#include <cstdint>
#include <string>

namespace flecsph::sph {
namespace detail {
/// Every checkpoint_every steps, and when the run stops before end_time (then with the command
/// that resumes it).
template<int D>
void checkpoint(app_state<D>& s) {
  const long every = s.files.checkpoint_every;
  const bool early = s.finished && !s.stop_reason.empty();
  if (!early && (every <= 0 || s.finished || s.step % every != 0)) return;
  const std::string& path = s.files.checkpoint_file;
  auto line = flecsi_lite::log::info();
  if (early)
    line << s.program << ": stopped at step " << s.step << ", t = " << s.time << " < end_time = " << s.run.end_time
         << ": " << s.stop_reason << "; ";
  if (path.empty()) {
    line << "no checkpoint (checkpoint_file = none): this run cannot be resumed";
    return;
  }
  complete_deferred_fields(s);  // every particle's phi (gravity.hh)
  write_restart_checkpoint(s, path,
                           {{"program", s.program},
                            {"parameters", s.parameters_text},
                            {"next_output", s.next_output},
                            {"output_due", std::int64_t{s.output_due}}});
  line << "checkpoint of step " << s.step << " (t = " << s.time << ") in '" << path << "'";
  if (!early) return;
  line << "; resume with\n  " << s.resume_command << " --set restart_file=" << path;
  // max_steps counts from step 0: the same value would stop the resumed run at once.
  if (s.run.max_steps > 0 && s.step >= s.run.max_steps)
    line << " --set max_steps=0\n(max_steps counts steps from t = 0: 0 runs to end_time, a larger value stops there)";
}
}  // namespace detail
}  // namespace flecsph::sph
