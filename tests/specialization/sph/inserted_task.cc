// An app's task placed inside the SPH step by name, on 1, 2 and 4 ranks: a uniform external
// acceleration g added right after "forces" (so before "kick", and before the clock moves) in
// initialize and in every advance. On every rank and every step it runs after exactly the
// physics actions that precede it, at the step's start time, and the total momentum then grows
// by exactly M g t (both half kicks see g; SPH forces conserve momentum to round-off).
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

/// What the test watches: the actions of each control point as they ran (one list per visit of
/// the point), and every run of the task in advance.
struct recorder {
  std::vector<std::vector<std::string>> initialize_runs, advance_runs;
  std::vector<double> advance_start_times;  ///< s.time when each advance began
  struct visit {
    long step;
    double time;
    std::size_t actions_before;  ///< actions of this advance that ran before the task
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
  m.action("initialize", "external_force", push).after("forces");
  m.action("advance", "external_force",
           [&seen](pushed_run& s) {
             push(s);
             seen.task_visits.push_back({s.step, s.time, seen.advance_runs.back().size() - 1});
           })
    .after("forces");
  m.observe([&seen](const std::string& point, const std::string& action, const pushed_run& s) {
    if (point != "initialize" && point != "advance") return;
    auto& runs = point == "initialize" ? seen.initialize_runs : seen.advance_runs;
    if (runs.empty() || action == (point == "advance" ? "kick_drift" : "search")) {
      runs.emplace_back();
      if (point == "advance") seen.advance_start_times.push_back(s.time);
    }
    runs.back().push_back(action);
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

  const std::vector<std::string> initialize{"search",         "density",         "equation_of_state", "forces",
                                            "external_force", "first_time_step", "diagnostics"};
  REQUIRE(seen.initialize_runs.size() == 1);
  CHECK(seen.initialize_runs[0] == initialize);
  const std::vector<std::string> advance{"kick_drift", "search",         "density", "equation_of_state",
                                         "forces",     "external_force", "kick",    "clock"};
  REQUIRE(seen.advance_runs.size() == 12);
  for (const auto& run : seen.advance_runs) CHECK(run == advance);
  // Once per step, before the clock moved: at the step's own number and start time.
  REQUIRE(seen.task_visits.size() == 12);
  for (std::size_t k = 0; k < seen.task_visits.size(); ++k) {
    CHECK(seen.task_visits[k].step == static_cast<long>(k));
    CHECK(seen.task_visits[k].time == seen.advance_start_times[k]);
    CHECK(seen.task_visits[k].actions_before == 5);  // kick_drift, search, density, EOS, forces
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
  CHECK(placed == 2);  // in initialize and in advance
  CHECK(text.find("label=\"external_force\", style=\"rounded,filled\"") != std::string::npos);
}
