// The control model: action order from dependencies, cycles of control points, clear errors.
#include <catch2/catch.hpp>

#include "flecsi_lite/control/control_model.hh"

#include <sstream>

using flecsi_lite::control::control_error;
using flecsi_lite::control::control_model;

namespace {
struct state {
  int step = 0;
  std::vector<std::string> log;
};
auto logger(const std::string& what) {
  return [what](state& s) { s.log.push_back(what + std::to_string(s.step)); };
}
}  // namespace

TEST_CASE("actions run in dependency order, ties in registration order") {
  control_model<state> m;
  m.point("initialize").point("advance");
  auto forces = m.action("advance", "forces", logger("forces"));
  auto density = m.action("advance", "density", logger("density"));
  auto eos = m.action("advance", "eos", logger("eos"));
  auto output = m.action("advance", "output", logger("output"));
  m.depends(eos, density).depends(forces, eos);
  CHECK(m.order("advance") == std::vector<std::string>{"density", "eos", "forces", "output"});
  (void)output;
}

TEST_CASE("a cycle repeats its control points while the predicate holds") {
  control_model<state> m;
  m.point("initialize")
    .cycle("main", {"advance", "analyze"}, [](const state& s) { return s.step < 3; })
    .point("finalize");
  m.action("initialize", "init", logger("init"));
  m.action("advance", "step", [](state& s) { ++s.step; });
  m.action("analyze", "look", logger("look"));
  m.action("finalize", "end", logger("end"));
  state s;
  m.run(s);
  CHECK(s.log == std::vector<std::string>{"init0", "look1", "look2", "look3", "end3"});
}

TEST_CASE("a dependency cycle is a start-up error naming its actions") {
  control_model<state> m;
  m.point("advance");
  auto a = m.action("advance", "density", logger("a"));
  auto b = m.action("advance", "pressure", logger("b"));
  auto c = m.action("advance", "forces", logger("c"));
  m.action("advance", "independent", logger("d"));
  m.depends(b, a).depends(c, b).depends(a, c);
  state s;
  CHECK_THROWS_AS(m.run(s), control_error);
  CHECK(s.log.empty());  // nothing ran
  CHECK_THROWS_WITH(m.order("advance"), Catch::Contains("dependency cycle") && Catch::Contains("density") &&
                                          Catch::Contains("pressure") && Catch::Contains("forces") &&
                                          !Catch::Contains("independent"));
}

TEST_CASE("misuse of the control model is reported clearly") {
  control_model<state> m;
  m.point("initialize").point("advance");
  CHECK_THROWS_WITH(m.action("advnace", "x", logger("x")), Catch::Contains("unknown control point 'advnace'"));
  auto a = m.action("initialize", "a", logger("a"));
  auto b = m.action("advance", "b", logger("b"));
  CHECK_THROWS_WITH(m.depends(b, a), Catch::Contains("another control point"));
  CHECK_THROWS_WITH(m.action("advance", "b", logger("b")), Catch::Contains("registered twice"));
  CHECK_THROWS_WITH(m.point("advance"), Catch::Contains("declared twice"));
}

TEST_CASE("the control model renders as a Graphviz graph with every point and action") {
  control_model<state> m;
  m.point("initialize").cycle("main", {"advance"}, [](const state&) { return false; });
  auto a = m.action("advance", "density", logger("a"));
  auto b = m.action("advance", "forces", logger("b"));
  m.depends(b, a);
  std::ostringstream dot;
  m.write_graphviz(dot, "test");
  const std::string text = dot.str();
  CHECK(text.rfind("digraph", 0) == 0);
  CHECK(text.find("label=\"density\"") != std::string::npos);
  CHECK(text.find("p1a0 -> p1a1") != std::string::npos);  // density -> forces
  CHECK(text.find("cycle: main") != std::string::npos);
  CHECK(text.find("repeat") != std::string::npos);
}

namespace {
/// The shape of the SPH step: a chain of physics actions that ends with the clock, and an
/// independent action registered after them.
control_model<state> step_model() {
  control_model<state> m;
  m.point("advance");
  auto drift = m.action("advance", "kick_drift", logger("kick_drift"));
  auto forces = m.action("advance", "forces", logger("forces"));
  auto kick = m.action("advance", "kick", logger("kick"));
  auto clock = m.action("advance", "clock", [](state& s) { ++s.step; });
  m.action("advance", "report", logger("report"));
  m.depends(forces, drift).depends(kick, forces).depends(clock, kick);
  return m;
}
}  // namespace

TEST_CASE("after(name) places an action right after its anchor, before the anchor's dependents") {
  auto m = step_model();
  m.action("advance", "cooling", logger("cooling")).after("forces");
  CHECK(m.order("advance") == std::vector<std::string>{"kick_drift", "forces", "cooling", "kick", "clock", "report"});
  // Appended without a place, it would run after the clock (ties broken by registration order).
  m.action("advance", "late", logger("late"));
  CHECK(m.order("advance").back() == "late");
}

TEST_CASE("before(name) places an action right before its anchor, after what the anchor waited on") {
  auto m = step_model();
  m.action("advance", "potential", logger("potential")).before("kick");
  m.action("advance", "first", logger("first")).before("kick_drift");
  CHECK(m.order("advance") ==
        std::vector<std::string>{"first", "kick_drift", "forces", "potential", "kick", "clock", "report"});
}

TEST_CASE("a placed action runs exactly next to its anchor even among independent actions") {
  control_model<state> m;
  m.point("analyze");
  m.action("analyze", "conserved", logger("conserved"));
  m.action("analyze", "progress", logger("progress"));
  m.action("analyze", "mine", logger("mine")).after("conserved");
  m.action("analyze", "theirs", logger("theirs")).before("conserved");
  CHECK(m.order("analyze") == std::vector<std::string>{"theirs", "conserved", "mine", "progress"});
}

TEST_CASE("actions placed after the same anchor run last-placed first; chains keep their order") {
  auto m = step_model();
  m.action("advance", "a", logger("a")).after("forces");
  m.action("advance", "b", logger("b")).after("forces");  // immediately after forces: before a
  m.action("advance", "c", logger("c")).after("a");
  CHECK(m.order("advance") ==
        std::vector<std::string>{"kick_drift", "forces", "b", "a", "c", "kick", "clock", "report"});
}

TEST_CASE("placed actions run in their place on every iteration of a cycle") {
  control_model<state> m;
  m.cycle("evolve", {"advance"}, [](const state& s) { return s.step < 2; });
  auto forces = m.action("advance", "forces", logger("forces"));
  auto clock = m.action("advance", "clock", [](state& s) { ++s.step; });
  m.depends(clock, forces);
  m.action("advance", "cooling", logger("cooling")).after("forces");
  m.action("advance", "stamp", logger("stamp")).before("clock");
  std::vector<std::string> seen;
  m.observe([&seen](const std::string& point, const std::string& action, const state& s) {
    seen.push_back(point + "/" + action + std::to_string(s.step));
  });
  state s;
  m.run(s);
  CHECK(s.log == std::vector<std::string>{"forces0", "cooling0", "stamp0", "forces1", "cooling1", "stamp1"});
  CHECK(seen == std::vector<std::string>{"advance/forces0", "advance/cooling0", "advance/stamp0", "advance/clock0",
                                         "advance/forces1", "advance/cooling1", "advance/stamp1", "advance/clock1"});
}

TEST_CASE("actions are found by name; a wrong name is reported with the point's actions") {
  auto m = step_model();
  const auto kick = m.find("advance", "kick");
  CHECK(kick.index == 2);
  auto check = m.action("advance", "check", logger("check"));
  m.depends(check, m.find("advance", "clock"));
  CHECK(m.order("advance").back() == "check");
  CHECK_THROWS_WITH(m.find("advance", "forcs"), Catch::Contains("no action 'forcs'") &&
                                                  Catch::Contains("control point 'advance'") &&
                                                  Catch::Contains("kick_drift, forces, kick, clock, report"));
  CHECK_THROWS_WITH(m.action("advance", "x", logger("x")).after("kik"),
                    Catch::Contains("no action 'kik'") && Catch::Contains("control point 'advance'"));
  CHECK_THROWS_WITH(m.find("advnace", "kick"), Catch::Contains("unknown control point 'advnace'"));
  auto twice = m.action("advance", "twice", logger("twice"));
  twice.after("forces");
  CHECK_THROWS_WITH(twice.before("kick"), Catch::Contains("already placed after forces"));
  CHECK_THROWS_WITH(m.action("advance", "self", logger("self")).after("self"), Catch::Contains("itself"));
}

TEST_CASE("the Graphviz output shows a placed action, marked, between its anchor and its dependents") {
  auto m = step_model();
  m.action("advance", "cooling", logger("cooling")).after("forces");
  std::ostringstream dot;
  m.write_graphviz(dot, "test");
  const std::string text = dot.str();
  // Actions of point 0: kick_drift a0, forces a1, kick a2, clock a3, report a4, cooling a5.
  CHECK(text.find("p0a5 [label=\"cooling\", style=\"rounded,filled\"") != std::string::npos);
  CHECK(text.find("placed after forces") != std::string::npos);
  CHECK(text.find("p0a1 -> p0a5") != std::string::npos);                  // forces -> cooling
  CHECK(text.find("p0a5 -> p0a2") != std::string::npos);                  // cooling -> kick
  CHECK(text.find("p0a1 -> p0a2") == std::string::npos);                  // no longer forces -> kick directly
  CHECK(text.find("p0a0 [label=\"kick_drift\"];") != std::string::npos);  // unplaced: plain
}

TEST_CASE("replace swaps an action's function and keeps its name, place and dependencies") {
  control_model<state> m;
  m.point("advance");
  auto density = m.action("advance", "density", logger("summation"));
  auto forces = m.action("advance", "forces", logger("forces"));
  m.action("advance", "cooling", logger("cooling")).after("density");
  m.depends(forces, density);
  const auto handle = m.replace("advance", "density", logger("continuity"));
  CHECK(handle.index == flecsi_lite::control::action_handle(density).index);
  CHECK(m.order("advance") == std::vector<std::string>{"density", "cooling", "forces"});
  state s;
  m.run(s);
  CHECK(s.log == std::vector<std::string>{"continuity0", "cooling0", "forces0"});
  CHECK_THROWS_AS(m.replace("advance", "no_such_action", logger("x")), control_error);
}

TEST_CASE("a stage declared once runs wherever an action runs it, a task placed in it with it") {
  control_model<state> m;
  m.point("initialize").cycle("main", {"advance"}, [](const state& s) { return s.step < 2; }).point("finalize");
  m.stage("evaluate");
  auto density = m.action("evaluate", "density", logger("density"));
  auto forces = m.action("evaluate", "forces", logger("forces"));
  m.depends(forces, density);
  auto start = m.action("initialize", "start", logger("start"));
  auto at_start = m.run_stage("initialize", "evaluate");
  m.depends(at_start, start);
  auto drift = m.action("advance", "drift", logger("drift"));
  auto in_step = m.run_stage("advance", "evaluate");
  auto clock = m.action("advance", "clock", [](state& s) { ++s.step; });
  m.depends(in_step, drift).depends(clock, in_step);
  m.action("evaluate", "cooling", logger("cooling")).after("forces");  // placed once
  m.action("finalize", "end", logger("end"));
  state s;
  m.run(s);
  CHECK(s.log == std::vector<std::string>{"start0", "density0", "forces0", "cooling0", "drift0", "density0", "forces0",
                                          "cooling0", "drift1", "density1", "forces1", "cooling1", "end2"});
  std::ostringstream dot;
  m.write_graphviz(dot, "test");
  CHECK(dot.str().find("label=\"stage: evaluate\"") != std::string::npos);
  CHECK(dot.str().find("label=\"runs\"") != std::string::npos);
}

TEST_CASE("a stage runs only when its condition holds; stages are run by points, not by stages") {
  control_model<state> m;
  m.point("initialize").point("finalize");
  m.stage("evaluate").stage("inner");
  m.action("evaluate", "forces", logger("forces"));
  m.run_stage("initialize", "evaluate", [](const state& s) { return s.step > 0; });
  m.action("finalize", "end", logger("end"));
  state s;
  m.run(s);
  CHECK(s.log == std::vector<std::string>{"end0"});
  CHECK_THROWS_WITH(m.run_stage("evaluate", "inner"), Catch::Contains("stages run from control points only"));
  CHECK_THROWS_WITH(m.run_stage("finalize", "initialize"), Catch::Contains("not a stage"));
}
