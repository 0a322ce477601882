// An app's task placed ONCE inside the SPH step by name, on 1, 2 and 4 ranks: a uniform external
// acceleration g added right after "forces" of the force_evaluation stage (so before "kick", and
// before the clock moves). It runs in the first force evaluation (initialize, t = 0) and in every
// later one (each advance), after exactly the physics actions that precede it, at the step's
// start time, and the total momentum then grows by exactly M g t (both half kicks of every step
// see g, the first one only if the evaluation at t = 0 had it; SPH forces conserve momentum to
// round-off).
#include "sph_setup.hh"

#include <catch2/catch.hpp>

#include <cmath>
#include <sstream>
#include <string>
#include <vector>

namespace {
using namespace sph_test;
constexpr int D = 2;

/// The task the app adds: a uniform external acceleration on the fluid particles.
void external_acceleration(sph::vector<D> g, sph::ro<sph::particle_kind> kind, sph::rw<sph::vector<D>> acceleration) {
  flecsi_lite::forall(
    acceleration.size(),
    [&](std::size_t a) {
      if (kind(a) != sph::particle_kind::fluid) return;
      for (int k = 0; k < D; ++k) acceleration(a)[k] += g[k];
    },
    "test::external_acceleration");
}

struct pushed_run : sph::simulation<D> {
  lattice shape{16, true, 1.0, 1.0, 0.2, 0.3, 0.3};
  sph::vector<D> g{0.3, -0.2};
};

/// What the test watches: the actions of each visit of initialize and advance as they ran, those
/// of the stage they ran prefixed "force_evaluation/", and every run of the task.
struct recorder {
  std::vector<std::vector<std::string>> initialize_runs, advance_runs;
  std::vector<std::vector<std::string>>* current = nullptr;  ///< the point being visited
  std::vector<double> advance_start_times;                   ///< s.time when each advance began
  struct visit {
    bool initializing;
    long step;
    double time;
    std::size_t actions_before;  ///< actions of this visit that ran before the task
  };
  std::vector<visit> task_visits;
};

void push(pushed_run& s) {
  using f = sph::fields<D>;
  auto& p = *s.particles;
  flecsi_lite::execute<external_acceleration>(s.g, f::kind(p), f::acceleration(p));
}

flecsi_lite::control::control_model<pushed_run> pushed_model(recorder& seen) {
  auto m = sph::make_control_model<pushed_run>();
  m.action("initial_data", "lattice", [](pushed_run& s) { load_lattice(s, s.shape); });
  // The one placement: the stage runs in initialize and in every advance.
  m.action("force_evaluation", "external_force",
           [&seen](pushed_run& s) {
             push(s);
             seen.task_visits.push_back({s.initializing, s.step, s.time, seen.current->back().size() - 1});
           })
    .after("forces");
  m.observe([&seen](const std::string& point, const std::string& action, const pushed_run& s) {
    if (point == "initialize" || point == "advance") {
      seen.current = point == "initialize" ? &seen.initialize_runs : &seen.advance_runs;
      if (action == (point == "advance" ? "kick_drift" : "start")) {
        seen.current->emplace_back();
        if (point == "advance") seen.advance_start_times.push_back(s.time);
      }
      seen.current->back().push_back(action);
    } else if (point == "force_evaluation") {
      seen.current->back().push_back(point + "/" + action);
    }
  });
  return m;
}
}  // namespace

TEST_CASE("a task placed after forces runs there on every rank, every step", "[sph][control]") {
  pushed_run s;
  s.physics.courant = 0.3;
  s.physics.eos.ideal.gamma = 1.4;
  s.run.end_time = 1.0;
  s.run.max_steps = 12;
  s.run.progress_every = 0;
  s.run.diagnostics_every = 0;
  recorder seen;
  auto m = pushed_model(seen);
  m.run(s);
  REQUIRE(s.step == 12);

  const std::vector<std::string> evaluation{"force_evaluation",
                                            "force_evaluation/search",
                                            "force_evaluation/density",
                                            "force_evaluation/equation_of_state",
                                            "force_evaluation/viscosity_switch",
                                            "force_evaluation/forces",
                                            "force_evaluation/external_force"};
  std::vector<std::string> initialize{"start"};
  initialize.insert(initialize.end(), evaluation.begin(), evaluation.end());
  initialize.insert(initialize.end(), {"first_time_step", "diagnostics"});
  REQUIRE(seen.initialize_runs.size() == 1);
  CHECK(seen.initialize_runs[0] == initialize);
  std::vector<std::string> advance{"kick_drift"};
  advance.insert(advance.end(), evaluation.begin(), evaluation.end());
  advance.insert(advance.end(), {"kick", "clock"});
  REQUIRE(seen.advance_runs.size() == 12);
  for (const auto& run : seen.advance_runs) CHECK(run == advance);
  // In the first force evaluation (initialize, t = 0), then once per step before the clock moved,
  // at the step's own number and start time.
  REQUIRE(seen.task_visits.size() == 13);
  CHECK(seen.task_visits[0].initializing);
  CHECK(seen.task_visits[0].step == 0);
  CHECK(seen.task_visits[0].time == 0.0);
  // start, the stage, search, density, EOS, viscosity_switch, forces
  CHECK(seen.task_visits[0].actions_before == 7);
  for (std::size_t k = 1; k < seen.task_visits.size(); ++k) {
    CHECK(!seen.task_visits[k].initializing);
    CHECK(seen.task_visits[k].step == static_cast<long>(k - 1));
    CHECK(seen.task_visits[k].time == seen.advance_start_times[k - 1]);
    // kick_drift, the stage, search, density, EOS, viscosity_switch, forces
    CHECK(seen.task_visits[k].actions_before == 7);
  }
  CHECK(seen.advance_start_times.back() < s.time);

  // Both half kicks of every step saw g: momentum grew by M g t (t summed exactly as the clock did).
  const double M = s.totals.mass;
  for (int k = 0; k < D; ++k) {
    const double gained = s.totals.momentum[k] - s.initial_totals.momentum[k];
    CHECK(std::fabs(gained - M * s.g[k] * s.time) < 1e-12);
    CHECK(std::fabs(gained) > 1e-3);  // g did act
  }
}

TEST_CASE("a restart skips the whole force evaluation at t = 0, the placed task with it", "[sph][control]") {
  recorder seen;
  auto m = pushed_model(seen);
  pushed_run s;
  s.restarted = true;  // what read_restart_checkpoint sets: the state of its step is complete
  s.run.end_time = 0;  // no step
  m.run(s);
  REQUIRE(seen.initialize_runs.size() == 1);
  CHECK(seen.initialize_runs[0] ==
        std::vector<std::string>{"start", "force_evaluation", "first_time_step", "diagnostics"});
  CHECK(seen.task_visits.empty());
  CHECK(!s.initializing);
}

TEST_CASE("the control model's Graphviz output shows the placed task", "[sph][control]") {
  recorder seen;
  const auto m = pushed_model(seen);
  std::ostringstream dot;
  m.write_graphviz(dot, "pushed");
  const std::string text = dot.str();
  std::size_t placed = 0;
  for (std::size_t at = text.find("placed after forces"); at != std::string::npos;
       at = text.find("placed after forces", at + 1))
    ++placed;
  CHECK(placed == 1);  // once, in the stage that initialize and advance run
  CHECK(text.find("label=\"external_force\", style=\"rounded,filled\"") != std::string::npos);
}
