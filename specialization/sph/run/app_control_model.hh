// The control model of an SPH app (app.hh): the standard model of the step (driver.hh) with
// self-gravity, the app's problem, the initial data or restart, the banner, the output series,
// the statistics, the run limits and the checkpoints, each placed at its control point.
//
//   auto m = sph::make_app_control_model<my_run>({set_domain, create_particles});
#pragma once

#include "specialization/sph/model/settings.hh"
#include "specialization/sph/model/walls.hh"
#include "specialization/sph/run/app_state.hh"
#include "specialization/sph/run/banner.hh"
#include "specialization/sph/run/checkpoints.hh"
#include "specialization/sph/run/initial_data.hh"
#include "specialization/sph/run/output_series.hh"
#include "specialization/sph/run/run_limits.hh"
#include "specialization/sph/run/statistics_rows.hh"
#include "specialization/sph/step/driver.hh"
#include "specialization/sph/step/gravity.hh"

#include "flecsi_lite/control.hh"
#include "flecsi_lite/runtime.hh"

#include <functional>

namespace flecsph::sph {
/// What an app adds to the standard model: the domain (box and periodic axes of
/// s.tree_settings) and, unless the particles come from a file, the particles themselves.
template<class State>
struct app_problem {
  std::function<void(State&)> set_domain;
  std::function<void(State&)> create_particles;
};

/// The standard SPH control model (driver.hh) with the self-gravity action (place_gravity, a
/// no-op unless gravity = on), the app's problem, the initial data, the output and the
/// checkpoints; the app adds its reports on "finalize".
template<class State>
flecsi_lite::control::control_model<State> make_app_control_model(app_problem<State> problem) {
  constexpr int D = State::dimension;
  using base = app_state<D>;
  auto m = make_control_model<State>();
  place_gravity(m);
  m.action("initial_data", "particles", [problem](State& s) {
    problem.set_domain(s);
    check_gravity_domain<D>(s.physics, s.tree_settings.periodic);
    if (!s.files.restart_file.empty()) {
      detail::restart<D>(s);  // has_walls as its checkpoint says
      return;
    }
    if (!s.files.initial_data.empty())
      detail::read_initial_particles<D>(s);
    else
      problem.create_particles(s);
    find_walls<D>(s);
  });
  m.action("initialize", "describe_particles", [](State& s) { detail::describe_particles<D>(s); })
    .after("force_evaluation");
  m.action("initialize", "open_output", [](State& s) { detail::open_output<D>(static_cast<base&>(s)); });
  m.action("initialize", "open_statistics", [](State& s) { detail::open_statistics<D>(s); }).after("diagnostics");
  m.action("analyze", "statistics", [](State& s) { detail::statistics_row<D>(s); }).after("conserved_quantities");
  m.action("analyze", "run_limits", [](State& s) { detail::check_run_limits<D>(s); }).before("conserved_quantities");
  auto output = m.action("output", "h5part", [](State& s) {
    if (s.writer || s.snapshots) detail::write_output_step<D>(s);
  });
  auto checkpoint = m.action("output", "checkpoint", [](State& s) { detail::checkpoint<D>(s); });
  m.depends(checkpoint, output);
  m.action("finalize", "close_output", [](State& s) {
    if (s.snapshots)
      flecsi_lite::log::info() << s.program << ": " << s.snapshots->written() << " snapshots indexed in "
                               << s.snapshots->index_path();
    if (!s.writer) return;
    s.writer->finish();  // renamed by commit_outputs(), after the app's checks
    flecsi_lite::log::info() << s.program << ": wrote " << s.writer->steps_written() << " steps to "
                             << s.files.output_file;
  });
  return m;
}
}  // namespace flecsph::sph
