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
} // namespace

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
