// The control model: a program is a sequence of CONTROL POINTS (e.g. initialize, advance,
// analyze, finalize), some of them grouped in a CYCLE repeated while a predicate holds. At each
// point run the ACTIONS registered on it, in an order that respects the declared DEPENDENCIES
// between actions of that point (topological sort; ties broken by registration order). A
// dependency cycle is an error at start-up that names the actions involved.
//
// A STAGE is a named group of actions, ordered like a point's, that is not in the sequence: an
// action of one or more points runs it (run_stage). What is written once in a stage runs
// wherever the stage runs, so a task placed in it once runs at every one of those places (the
// SPH step's force evaluation runs in "initialize" and in every "advance").
//
//   control_model<state> m;
//   m.point("initialize").cycle("main", {"advance", "analyze"}, [](state& s) { return s.step < 10; })
//    .point("finalize");
//   auto density = m.action("advance", "density", compute_density);
//   auto forces = m.action("advance", "forces", compute_forces);
//   m.depends(forces, density);   // forces after density
//   m.stage("evaluate");          // actions registered on a stage run where a point runs it:
//   m.run_stage("initialize", "evaluate");
//   return m.run(s);
#pragma once

#include "flecsi_lite/runtime/context.hh"
#include "flecsi_lite/runtime/runtime.hh"

#include <fstream>
#include <functional>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

namespace flecsi_lite::control {

struct control_error : std::runtime_error {
  using std::runtime_error::runtime_error;
};

/// Identifies an action: its control point and its index (registration order) there.
struct action_handle {
  std::size_t point;
  std::size_t index;
};

namespace detail {
/// The part of the model that does not depend on the state type.
class model_structure {
 public:
  struct action_info {
    std::string name;
    std::vector<std::size_t> after;  // indices of actions of the same point
    std::string placement;           // "after forces", "before kick", or empty when not placed
    std::size_t stage = npos;        // the stage this action runs (run_stage), or npos
  };
  struct point_info {
    std::string name;
    std::vector<action_info> actions;
    std::size_t cycle = npos;  // index into cycles_, or npos
    /// Tie-break order of the topological sort: registration order, except that a placed action
    /// sits next to its anchor, so that it runs exactly there.
    std::vector<std::size_t> sequence;
    bool is_stage = false;  // a stage: not in the sequence, run by actions of points
  };
  struct cycle_info {
    std::string name;
    std::size_t first_point, last_point;  // inclusive range of points
  };
  static constexpr std::size_t npos = static_cast<std::size_t>(-1);

  std::size_t add_point(const std::string& name, std::size_t cycle = npos);
  std::size_t add_cycle(const std::string& name, const std::vector<std::string>& points);
  std::size_t add_stage(const std::string& name);
  action_handle add_action(const std::string& point, const std::string& name);
  /// An action named after `stage` on `point` that runs the stage's actions; a stage runs no stage.
  action_handle add_stage_run(const std::string& point, const std::string& stage);
  void add_dependency(action_handle later, action_handle earlier);
  /// The action called `name` on `point`; throws control_error naming the point's actions.
  action_handle find_action(const std::string& point, const std::string& name) const;
  /// Places `action` immediately after `anchor`: it waits on the anchor, and every action that
  /// waited on the anchor waits on it instead.
  void place_after(action_handle action, const std::string& anchor);
  /// Places `action` immediately before `anchor`: it waits on what the anchor waited on, and the
  /// anchor waits on it.
  void place_before(action_handle action, const std::string& anchor);

  /// Actions of a point in execution order; throws control_error naming a dependency cycle.
  std::vector<std::size_t> order(std::size_t point) const;
  /// Checks every point (cycles among actions, empty cycles).
  void validate() const;
  void write_graphviz(std::ostream& out, const std::string& title) const;

  const std::vector<point_info>& points() const { return points_; }
  const std::vector<cycle_info>& cycles() const { return cycles_; }
  std::size_t find_point(const std::string& name) const;

 private:
  /// The anchor `action` may be placed next to; throws when it is placed already or is the anchor.
  action_handle placement_anchor(action_handle action, const std::string& anchor_name) const;

  std::vector<point_info> points_;
  std::vector<cycle_info> cycles_;
};
}  // namespace detail

/// What control_model::action returns: the new action's handle (it converts to action_handle),
/// which may still be placed once, relative to a named action of the same control point. Use it
/// at once: it refers to its model.
class new_action {
 public:
  new_action(detail::model_structure& structure, action_handle handle) : structure_(&structure), handle_(handle) {}
  operator action_handle() const { return handle_; }
  /// Runs right after `anchor`, before every action that depended on the anchor.
  action_handle after(const std::string& anchor) const {
    structure_->place_after(handle_, anchor);
    return handle_;
  }
  /// Runs right before `anchor`, after every action the anchor depended on.
  action_handle before(const std::string& anchor) const {
    structure_->place_before(handle_, anchor);
    return handle_;
  }

 private:
  detail::model_structure* structure_;
  action_handle handle_;
};

template<class State>
class control_model {
 public:
  using action_function = std::function<void(State&)>;
  using predicate = std::function<bool(const State&)>;
  /// Called before every action that runs, with its control point and name (tracing, tests).
  using observer = std::function<void(const std::string& point, const std::string& action, const State&)>;

  control_model& point(const std::string& name) {
    structure_.add_point(name);
    return *this;
  }
  /// A cycle of consecutive points, repeated while `keep_going(state)` holds (tested before
  /// each iteration).
  control_model& cycle(const std::string& name, const std::vector<std::string>& points, predicate keep_going) {
    structure_.add_cycle(name, points);
    predicates_.push_back(std::move(keep_going));
    return *this;
  }

  /// A stage: actions registered on it by name like a point's (action, depends, replace, find,
  /// order), that run only where an action of a point runs it (run_stage).
  control_model& stage(const std::string& name) {
    structure_.add_stage(name);
    return *this;
  }
  /// Registers on `point` an action named `stage` that runs the stage's actions in their order,
  /// when `when(state)` holds (always without it). Place it like any action.
  new_action run_stage(const std::string& point, const std::string& stage, predicate when = nullptr) {
    const action_handle h = structure_.add_stage_run(point, stage);
    if (functions_.size() <= h.point) functions_.resize(h.point + 1);
    if (conditions_.size() <= h.point) conditions_.resize(h.point + 1);
    functions_[h.point].emplace_back();
    conditions_[h.point].resize(h.index + 1);
    conditions_[h.point][h.index] = std::move(when);
    return {structure_, h};
  }
  /// Registers an action on `point`; unplaced, it runs after the actions registered before it
  /// that it does not precede by a dependency. `.after(name)` / `.before(name)` place it.
  new_action action(const std::string& point, const std::string& name, action_function f) {
    const action_handle h = structure_.add_action(point, name);
    if (functions_.size() <= h.point) functions_.resize(h.point + 1);
    functions_[h.point].push_back(std::move(f));
    return {structure_, h};
  }
  /// Replaces the function of the action `name` on `point`, keeping its name, place and
  /// dependencies: a specialization variant (e.g. another density or force pass) in one line.
  action_handle replace(const std::string& point, const std::string& name, action_function f) {
    const action_handle h = structure_.find_action(point, name);
    functions_[h.point][h.index] = std::move(f);
    return h;
  }
  /// `later` runs after `earlier`; both must belong to the same control point.
  control_model& depends(action_handle later, action_handle earlier) {
    structure_.add_dependency(later, earlier);
    return *this;
  }
  /// The action called `name` on `point` (a clear error naming the point's actions if none).
  action_handle find(const std::string& point, const std::string& name) const {
    return structure_.find_action(point, name);
  }
  void observe(observer f) { observer_ = std::move(f); }

  /// Execution order of the actions of `point`, by name.
  std::vector<std::string> order(const std::string& point) const {
    const std::size_t p = structure_.find_point(point);
    std::vector<std::string> names;
    for (std::size_t a : structure_.order(p)) names.push_back(structure_.points()[p].actions[a].name);
    return names;
  }
  void write_graphviz(std::ostream& out, const std::string& title = "control model") const {
    structure_.write_graphviz(out, title);
  }

  /// What a program's main calls: with --control-model, rank 0 writes the model as Graphviz
  /// (<program>-control-model.dot) and nothing runs; otherwise run(state). Returns an exit code.
  int execute(State& state) const {
    const auto& settings = runtime::current_settings();
    if (settings.control_model_file.empty()) {
      run(state);
      return 0;
    }
    structure_.validate();
    if (runtime::rank() == 0) {
      std::ofstream out(settings.control_model_file);
      write_graphviz(out, settings.program);
      if (!out) throw control_error("cannot write " + settings.control_model_file);
      std::cout << "control model written to " << settings.control_model_file << " (render: dot -Tpng "
                << settings.control_model_file << " -o model.png)\n";
    }
    return 0;
  }

  /// Validates the whole model, then runs it on `state`.
  void run(State& state) const {
    structure_.validate();
    std::vector<std::vector<std::size_t>> orders;
    for (std::size_t p = 0; p < structure_.points().size(); ++p) orders.push_back(structure_.order(p));
    const auto& points = structure_.points();
    for (std::size_t p = 0; p < points.size();) {
      if (points[p].is_stage) {  // run by the actions that name it
        ++p;
        continue;
      }
      if (points[p].cycle == detail::model_structure::npos) {
        run_point(p, orders, state);
        ++p;
        continue;
      }
      const auto& c = structure_.cycles()[points[p].cycle];
      while (predicates_[points[p].cycle](state))
        for (std::size_t q = c.first_point; q <= c.last_point; ++q) run_point(q, orders, state);
      p = c.last_point + 1;
    }
  }

 private:
  void run_point(std::size_t p, const std::vector<std::vector<std::size_t>>& orders, State& state) const {
    if (p >= functions_.size()) return;
    const auto& point = structure_.points()[p];
    for (std::size_t a : orders[p]) {
      if (observer_) observer_(point.name, point.actions[a].name, state);
      const std::size_t stage = point.actions[a].stage;
      if (stage == detail::model_structure::npos)
        functions_[p][a](state);
      else if (!conditions_[p][a] || conditions_[p][a](state))
        run_point(stage, orders, state);
    }
  }

  detail::model_structure structure_;
  std::vector<predicate> predicates_;
  std::vector<std::vector<action_function>> functions_;
  std::vector<std::vector<predicate>> conditions_;  // of the actions that run a stage
  observer observer_;
};

}  // namespace flecsi_lite::control
