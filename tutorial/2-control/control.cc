// Tutorial chapter 2: the control model (FleCSI's control points, actions and dependencies). A
// program is a sequence of control points, some grouped in a cycle repeated while a predicate
// holds; each point runs its actions in an order that respects their declared dependencies.
//
//   tutorial_2_control                   runs the model and checks the order of the actions
//   tutorial_2_control --control-model   writes tutorial_2_control-control-model.dot, runs nothing
#include "flecsi_lite/control.hh"
#include "flecsi_lite/runtime.hh"

#include <fstream>
#include <sstream>
#include <string>
#include <vector>

using namespace flecsi_lite;

namespace {
// The state the actions share: here, a step counter and the log of what ran.
struct state {
  int step = 0, steps = 3;
  std::vector<std::string> ran;
};

// An action is a function of the state. This helper makes one that records its own name.
control::control_model<state>::action_function record(const std::string& name) {
  return [name](state& s) { s.ran.push_back(name); };
}

control::control_model<state> make_model() {
  control::control_model<state> m;
  m.point("initialize")
    .cycle("evolve", {"advance", "analyze"}, [](const state& s) { return s.step < s.steps; })
    .point("finalize");
  m.action("initialize", "setup", record("setup"));
  // Registered in the "wrong" order: the dependencies decide, not the registration.
  auto forces = m.action("advance", "forces", record("forces"));
  auto density = m.action("advance", "density", record("density"));
  auto move = m.action("advance", "move", [](state& s) {
    s.ran.push_back("move");
    ++s.step;
  });
  m.depends(forces, density);  // forces after density
  m.depends(move, forces);     // move after forces
  m.action("analyze", "output", record("output"));
  m.action("finalize", "report", record("report"));
  return m;
}
}  // namespace

int main(int argc, char** argv) {
  runtime::runtime rt(argc, argv, runtime::options("Tutorial 2: control points, cycles, actions, dependencies."));
  if (!rt.proceed()) return rt.exit_code();
  const auto model = make_model();
  state s;
  // execute() runs the model, or with --control-model writes it as Graphviz and runs nothing.
  const int status = model.execute(s);
  const std::string dot_file = runtime::current_settings().control_model_file;
  if (status) return status;

  bool correct = true;
  if (!dot_file.empty()) {  // --control-model: nothing ran, the graph names every action
    std::ifstream in(dot_file);
    std::stringstream text;
    text << in.rdbuf();
    correct = s.ran.empty() && (runtime::rank() != 0 || (text.str().find("digraph") != std::string::npos &&
                                                         text.str().find("\"density\"") != std::string::npos));
  } else {
    std::vector<std::string> expected{"setup"};
    for (int step = 0; step < s.steps; ++step)
      for (const char* name : {"density", "forces", "move", "output"}) expected.push_back(name);
    expected.push_back("report");
    correct = s.ran == expected && model.order("advance") == std::vector<std::string>{"density", "forces", "move"};
  }

  // A dependency cycle is an error at start-up that names the actions involved.
  control::control_model<state> broken;
  broken.point("advance");
  auto a = broken.action("advance", "a", record("a"));
  auto b = broken.action("advance", "b", record("b"));
  broken.depends(a, b).depends(b, a);
  try {
    state t;
    broken.run(t);
    correct = false;
  } catch (const control::control_error& e) {
    log::info() << "as expected: " << e.what();
  }
  if (!correct) log::error() << "tutorial 2: the actions ran in the wrong order";
  return correct ? 0 : 1;
}
