#include "flecsi_lite/control/control_model.hh"

#include <algorithm>
#include <ostream>

namespace flecsi_lite::control::detail {

std::size_t model_structure::find_point(const std::string& name) const {
  for (std::size_t p = 0; p < points_.size(); ++p)
    if (points_[p].name == name) return p;
  std::string known;
  for (auto& p : points_) known += (known.empty() ? "" : ", ") + p.name;
  throw control_error("unknown control point '" + name + "' (control points: " + known + ")");
}

std::size_t model_structure::add_point(const std::string& name, std::size_t cycle) {
  for (auto& p : points_)
    if (p.name == name) throw control_error("control point '" + name + "' declared twice");
  points_.push_back({name, {}, cycle, {}, false});
  return points_.size() - 1;
}

std::size_t model_structure::add_cycle(const std::string& name, const std::vector<std::string>& names) {
  if (names.empty()) throw control_error("cycle '" + name + "' has no control points");
  const std::size_t c = cycles_.size();
  cycles_.push_back({name, points_.size(), points_.size() + names.size() - 1});
  for (auto& n : names) add_point(n, c);
  return c;
}

std::size_t model_structure::add_stage(const std::string& name) {
  const std::size_t p = add_point(name);
  points_[p].is_stage = true;
  return p;
}

action_handle model_structure::add_stage_run(const std::string& point, const std::string& stage) {
  const std::size_t s = find_point(stage);
  if (!points_[s].is_stage)
    throw control_error("'" + stage + "' is a control point, not a stage: only a stage is run by an action");
  if (points_[find_point(point)].is_stage)
    throw control_error("stage '" + point + "' cannot run stage '" + stage + "': stages run from control points only");
  const action_handle h = add_action(point, stage);
  points_[h.point].actions[h.index].stage = s;
  return h;
}

action_handle model_structure::add_action(const std::string& point, const std::string& name) {
  const std::size_t p = find_point(point);
  for (auto& a : points_[p].actions)
    if (a.name == name) throw control_error("action '" + name + "' registered twice on control point '" + point + "'");
  points_[p].actions.push_back({name, {}, {}});
  points_[p].sequence.push_back(points_[p].actions.size() - 1);
  return {p, points_[p].actions.size() - 1};
}

action_handle model_structure::find_action(const std::string& point, const std::string& name) const {
  const std::size_t p = find_point(point);
  const auto& actions = points_[p].actions;
  for (std::size_t a = 0; a < actions.size(); ++a)
    if (actions[a].name == name) return {p, a};
  std::string known;
  for (auto& a : actions) known += (known.empty() ? "" : ", ") + a.name;
  throw control_error("no action '" + name + "' on control point '" + point +
                      "' (its actions: " + (known.empty() ? "none" : known) + ")");
}

namespace {
/// Moves `action` in `sequence` to just before (offset 0) or just after (offset 1) `anchor`.
void move_next_to(std::vector<std::size_t>& sequence, std::size_t action, std::size_t anchor, std::size_t offset) {
  sequence.erase(std::find(sequence.begin(), sequence.end(), action));
  const auto at = std::find(sequence.begin(), sequence.end(), anchor);
  sequence.insert(at + static_cast<std::ptrdiff_t>(offset), action);
}
}  // namespace

action_handle model_structure::placement_anchor(action_handle action, const std::string& anchor_name) const {
  const auto& point = points_[action.point];
  const action_handle anchor = find_action(point.name, anchor_name);
  const auto& placed = point.actions[action.index];
  if (!placed.placement.empty())
    throw control_error("action '" + placed.name + "' (" + point.name + ") is already placed " + placed.placement);
  if (anchor.index == action.index)
    throw control_error("action '" + placed.name + "' (" + point.name + ") cannot be placed relative to itself");
  return anchor;
}

void model_structure::place_after(action_handle action, const std::string& anchor_name) {
  auto& point = points_[action.point];
  const action_handle anchor = placement_anchor(action, anchor_name);
  auto& placed = point.actions[action.index];
  // The anchor's dependents now wait on the new action, which waits on the anchor.
  for (std::size_t a = 0; a < point.actions.size(); ++a) {
    if (a == action.index) continue;
    for (std::size_t& earlier : point.actions[a].after)
      if (earlier == anchor.index) earlier = action.index;
  }
  placed.after.push_back(anchor.index);
  placed.placement = "after " + anchor_name;
  move_next_to(point.sequence, action.index, anchor.index, 1);
}

void model_structure::place_before(action_handle action, const std::string& anchor_name) {
  auto& point = points_[action.point];
  const action_handle anchor = placement_anchor(action, anchor_name);
  auto& placed = point.actions[action.index];
  // The new action inherits what the anchor waited on, and the anchor waits on it alone.
  auto& waited = point.actions[anchor.index].after;
  for (std::size_t earlier : waited) placed.after.push_back(earlier);
  waited.assign(1, action.index);
  placed.placement = "before " + anchor_name;
  move_next_to(point.sequence, action.index, anchor.index, 0);
}

void model_structure::add_dependency(action_handle later, action_handle earlier) {
  if (later.point != earlier.point)
    throw control_error("action '" + points_[later.point].actions[later.index].name + "' (" +
                        points_[later.point].name + ") cannot depend on action '" +
                        points_[earlier.point].actions[earlier.index].name + "' of another control point (" +
                        points_[earlier.point].name + ")");
  points_[later.point].actions[later.index].after.push_back(earlier.index);
}

std::vector<std::size_t> model_structure::order(std::size_t point) const {
  // Kahn's algorithm, always taking the ready action earliest in the point's sequence
  // (registration order with placed actions next to their anchors).
  const auto& actions = points_[point].actions;
  const auto& sequence = points_[point].sequence;
  const std::size_t n = actions.size();
  std::vector<std::size_t> waiting_on(n, 0);
  std::vector<std::vector<std::size_t>> successors(n);
  for (std::size_t a = 0; a < n; ++a)
    for (std::size_t b : actions[a].after) {
      ++waiting_on[a];
      successors[b].push_back(a);
    }
  std::vector<std::size_t> result;
  std::vector<bool> done(n, false);
  while (result.size() < n) {
    std::size_t next = n;
    for (std::size_t k = 0; k < n && next == n; ++k)
      if (!done[sequence[k]] && waiting_on[sequence[k]] == 0) next = sequence[k];
    if (next == n) {
      // Every remaining action waits on another: follow "waits on" links to exhibit a cycle.
      std::size_t a = 0;
      while (done[a]) ++a;
      std::vector<std::size_t> path;
      std::vector<int> seen(n, -1);
      while (seen[a] < 0) {
        seen[a] = static_cast<int>(path.size());
        path.push_back(a);
        for (std::size_t b : actions[a].after)
          if (!done[b]) {
            a = b;
            break;
          }
      }
      std::string chain;
      for (std::size_t i = seen[a]; i < path.size(); ++i) chain += actions[path[i]].name + " -> ";
      chain += actions[a].name;
      throw control_error("dependency cycle among the actions of control point '" + points_[point].name +
                          "': " + chain + " (each waits on the next)");
    }
    done[next] = true;
    result.push_back(next);
    for (std::size_t s : successors[next]) --waiting_on[s];
  }
  return result;
}

void model_structure::validate() const {
  for (std::size_t p = 0; p < points_.size(); ++p) order(p);
}

void model_structure::write_graphviz(std::ostream& out, const std::string& title) const {
  out << "digraph control_model {\n  label=\"" << title << "\";\n  compound=true;\n  rankdir=TB;\n"
      << "  node [shape=box, style=rounded];\n";
  std::size_t open_cycle = npos;
  for (std::size_t p = 0; p < points_.size(); ++p) {
    const auto& point = points_[p];
    if (point.cycle != open_cycle && open_cycle != npos) {
      out << "  }\n";
      open_cycle = npos;
    }
    if (point.cycle != npos && point.cycle != open_cycle) {
      open_cycle = point.cycle;
      out << "  subgraph cluster_cycle_" << open_cycle << " {\n    label=\"cycle: " << cycles_[open_cycle].name
          << "\";\n    style=dashed;\n";
    }
    out << "  subgraph cluster_point_" << p << " {\n    label=\"" << (point.is_stage ? "stage: " : "") << point.name
        << "\";\n    style=filled; fillcolor=\"" << (point.is_stage ? "#eaf5e4" : "#eef3fb") << "\";\n    p" << p
        << " [shape=point, style=invis];\n";
    // Placed actions (what an app inserted into someone else's point) stand out.
    for (std::size_t a = 0; a < point.actions.size(); ++a) {
      out << "    p" << p << "a" << a << " [label=\"" << point.actions[a].name << "\"";
      if (point.actions[a].stage != npos) out << ", shape=box3d";
      if (!point.actions[a].placement.empty())
        out << ", style=\"rounded,filled\", fillcolor=\"#fdd9a8\", tooltip=\"placed " << point.actions[a].placement
            << "\"";
      out << "];\n";
    }
    for (std::size_t a = 0; a < point.actions.size(); ++a)
      for (std::size_t b : point.actions[a].after) out << "    p" << p << "a" << b << " -> p" << p << "a" << a << ";\n";
    out << "  }\n";
  }
  if (open_cycle != npos) out << "  }\n";
  // Control flow between points (stages aside), the back edge of each cycle, and each action
  // that runs a stage to that stage.
  std::size_t previous = npos;
  for (std::size_t p = 0; p < points_.size(); ++p) {
    if (points_[p].is_stage) continue;
    if (previous != npos)
      out << "  p" << previous << " -> p" << p << " [ltail=cluster_point_" << previous << ", lhead=cluster_point_" << p
          << ", color=\"#1f77b4\", penwidth=2];\n";
    previous = p;
  }
  for (std::size_t p = 0; p < points_.size(); ++p)
    for (std::size_t a = 0; a < points_[p].actions.size(); ++a)
      if (const std::size_t stage = points_[p].actions[a].stage; stage != npos)
        out << "  p" << p << "a" << a << " -> p" << stage << " [lhead=cluster_point_" << stage
            << ", color=\"#2ca02c\", style=dotted, label=\"runs\"];\n";
  for (const auto& c : cycles_)
    out << "  p" << c.last_point << " -> p" << c.first_point << " [ltail=cluster_point_" << c.last_point
        << ", lhead=cluster_point_" << c.first_point << ", color=\"#d62728\", style=dashed, label=\"repeat\"];\n";
  out << "}\n";
}

}  // namespace flecsi_lite::control::detail
