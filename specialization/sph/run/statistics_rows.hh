// The rows of an SPH run's statistics file (statistics.hh holds the file and its format): the
// header and first row at the start, a row every statistics_every steps and at the last one.
#pragma once

#include "specialization/sph/run/app_state.hh"
#include "specialization/sph/run/statistics.hh"
#include "specialization/sph/step/diagnostics.hh"

#include "flecsi_lite/app.hh"
#include "flecsi_lite/runtime.hh"

#include <optional>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

namespace flecsph::sph {
namespace detail {
/// Neighbours per particle over all ranks (the progress line's mean, at any step).
template<int D>
double mean_neighbours(const app_state<D>& s) {
  return mean_list_length(s);
}

/// The values of the app's own statistics columns (none unless it set extra_statistics).
template<int D>
std::vector<double> extra_statistics_values(app_state<D>& s) {
  return s.extra_statistics ? s.extra_statistics() : std::vector<double>();
}

/// The first row of a new run; a restart writes none for its restart step (the run it continues did).
template<int D>
void open_statistics(app_state<D>& s) {
  s.statistics_dt = s.dt;
  if (s.statistics_keys.file.empty()) return;
  const std::vector<std::string> description = {
    s.program + " statistics: a row every " + std::to_string(s.statistics_keys.every) +
      " steps and at the last one, written by rank 0 and flushed row by row",
    s.program + " " + flecsi_lite::app::version() + " (git " + flecsi_lite::app::git_describe() + "), " +
      std::to_string(flecsi_lite::runtime::size()) + " MPI ranks; " +
      (s.physics.gravity.enabled ? "self-gravity: total = kinetic + internal + potential + walls"
                                 : "no gravity, so no potential energy column"),
    "parameters:"};
  std::string header;
  {
    std::vector<std::string> lines = description;
    std::istringstream parameters(s.parameters_text);
    for (std::string line; std::getline(parameters, line);) lines.push_back("  " + line);
    header = statistics_header<D>(lines, s.physics.gravity.enabled, s.extra_statistics_columns);
  }
  s.statistics.open(s.statistics_keys.file, header, s.restarted ? std::optional<long>(s.step) : std::nullopt);
  if (!s.restarted)
    s.statistics.write(statistics_line<D>(s.step, s.time, 0.0, measure_conserved(s), mean_neighbours(s),
                                          s.physics.gravity.enabled, extra_statistics_values(s)));
}

/// A row every statistics_every steps and at the last; the totals of the conserved line when it
/// measured them at this step, else measured here (and kept in s.totals for the app's checks).
template<int D>
void statistics_row(app_state<D>& s) {
  const double dt = std::exchange(s.statistics_dt, s.dt);
  if (!s.statistics.is_open() || !(s.finished || s.step % s.statistics_keys.every == 0)) return;
  if (s.totals_step != s.step) {
    s.totals = measure_conserved(s);
    s.totals_step = s.step;
  }
  s.statistics.write(statistics_line<D>(s.step, s.time, dt, s.totals, mean_neighbours(s), s.physics.gravity.enabled,
                                        extra_statistics_values(s)));
}
}  // namespace detail
}  // namespace flecsph::sph
