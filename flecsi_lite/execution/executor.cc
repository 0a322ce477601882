// The executor (executor.hh): dependency bookkeeping per field and region, eager and packed ghost
// copies, scheduling rounds (communication first), polling between loop chunks, failures and
// cancellation.
#include "flecsi_lite/execution/executor.hh"

#include "flecsi_lite/execution/detail/ghost_copy.hh"
#include "flecsi_lite/execution/forall.hh"
#include "flecsi_lite/runtime/context.hh"
#include "flecsi_lite/runtime/log.hh"
#include "flecsi_lite/runtime/runtime.hh"
#include "flecsi_lite/runtime/timers.hh"

#include <algorithm>
#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iostream>
#include <stdexcept>

namespace flecsi_lite::execution {
namespace {
const char* kind_name(launch_kind k) {
  return k == launch_kind::task              ? "task"
         : k == launch_kind::ghost_copy      ? "ghost_copy"
         : k == launch_kind::ghost_reduction ? "ghost_reduction"
                                             : "reduction";
}
std::string what_of(const std::exception_ptr& error) {
  try {
    std::rethrow_exception(error);
  } catch (const std::exception& e) {
    return e.what();
  } catch (...) {
    return "an exception that is not a std::exception";
  }
}
// Tags of ghost-copy messages: distinct for copies that may be in flight together.
constexpr int first_copy_tag = 1000, copy_tag_count = 30000;
// Launches recorded ahead of execution before the executor starts running them.
constexpr std::size_t window = 128;
}  // namespace

executor& executor::instance() {
  static executor* the_executor = new executor();  // outlives static destructors and MPI
  return *the_executor;
}

executor::executor() : epoch_(std::chrono::steady_clock::now()) {
  data::set_layout_listener(this);
  flecsi_lite::detail::poll_hook = [] { return executor::instance().poll(); };
  const std::string trace_file = runtime::current_settings().trace_file;
  tracing_ = !trace_file.empty();
  runtime::at_finalize([this, trace_file] {
    // After a failure the other ranks wait for this one's messages: end them all.
    if (failures_ && runtime::size() > 1) abort_run();
    try {
      wait_all();
    } catch (const std::exception& e) {
      log::error() << "flecsi_lite: " << e.what();
    }
    if (runtime::current_settings().timers) detail::report_ghost_traffic(traffic_, std::cout);
    if (trace_file.empty()) return;
    // Written beside and renamed once complete, as every output: a full disk or a crash never
    // leaves half a trace (or nothing) under the name, and a failure is said.
    const std::string partial = trace_file + ".partial";
    std::ofstream out;
    if (runtime::rank() == 0) out.open(partial, std::ios::trunc);
    write_chrome_trace(trace_, out);
    if (runtime::rank() != 0) return;
    out.close();
    if (!out || std::rename(partial.c_str(), trace_file.c_str()) != 0) {
      log::error() << "flecsi_lite: the --trace file '" << trace_file << "' was not written: cannot write '" << partial
                   << "' (" << std::strerror(errno) << ")";
      std::remove(partial.c_str());
    }
  });
}

executor::~executor() {
  data::set_layout_listener(nullptr);
  flecsi_lite::detail::poll_hook = nullptr;
}

double executor::now() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - epoch_).count();
}

void executor::add_dependencies(launch& l, field_state& state, region r, privilege p) {
  region_state& rs = state.regions[static_cast<int>(r)];
  if (p == na) return;
  enum how { result, order, start };
  auto depend_on = [&l](const launch_ptr& other, how h) {
    if (!other || other->state == launch_state::done) return;
    if (h == start && other->state == launch_state::in_flight) return;
    (h == result ? l.dependencies : h == order ? l.ordered_after : l.started).push_back(other);
    l.dependency_sequences.push_back(other->sequence);
  };
  depend_on(rs.last_writer, reads(p) ? result : order);  // read after write, write after write
  if (writes(p))
    for (auto& reader : rs.readers)  // write after read; a copy reads owned values when it starts
      depend_on(reader, reader->kind == launch_kind::ghost_copy && r == region::owned ? start : order);
}

template<class Wanted>
void executor::record_ghost_copies(const std::vector<field_access>& accesses, Wanted wanted) {
  std::vector<std::vector<const field_access*>> groups;  // stale fields, per topology
  for (const auto& a : accesses) {
    field_state& state = fields_[{a.instance, a.field}];
    if (state.ghosts_valid || !wanted(a, state)) continue;
    auto group =
      std::find_if(groups.begin(), groups.end(), [&a](const auto& g) { return g.front()->topology == a.topology; });
    if (group == groups.end())
      groups.push_back({&a});
    else if (std::none_of(group->begin(), group->end(), [&a](const field_access* b) { return b->field == a.field; }))
      group->push_back(&a);
  }
  for (const auto& group : groups) record_ghost_copy(group);
}

launch_ptr executor::record(std::string name, launch_kind kind, const std::vector<field_access>& accesses,
                            std::vector<launch_ptr> after, std::function<void(launch&)> start,
                            std::function<void()> finish) {
  if (inside_launch_) throw std::logic_error("executor: task '" + name + "' launched from inside a running task");
  auto l = std::make_shared<launch>();
  l->name = std::move(name);
  l->kind = kind;
  l->start = std::move(start);
  l->finish = std::move(finish);
  for (auto& a : after)
    if (a && a->state != launch_state::done) {
      l->dependencies.push_back(a);
      l->dependency_sequences.push_back(a->sequence);
    }

  // Stale ghosts this launch reads (normally copied eagerly already): one copy per topology.
  record_ghost_copies(accesses, [](const field_access& a, field_state&) { return reads(a.ghost); });
  for (const auto& a : accesses) {
    field_state& state = fields_[{a.instance, a.field}];
    add_dependencies(*l, state, region::owned, a.owned);
    add_dependencies(*l, state, region::ghost, a.ghost);
  }
  // Update the bookkeeping only after all dependencies are known (a field may appear twice).
  for (const auto& a : accesses) {
    field_state& state = fields_[{a.instance, a.field}];
    const privilege privileges[2] = {a.owned, a.ghost};
    for (int r = 0; r < 2; ++r) {
      if (privileges[r] == na) continue;
      region_state& rs = state.regions[r];
      if (writes(privileges[r])) {
        rs.last_writer = l;
        rs.readers.clear();
      } else {
        rs.readers.push_back(l);
      }
    }
    if (reads(a.ghost)) {
      state.ghosts_read = true;
      state.eager_after.clear();  // the eager copy served a reader
    }
    if (writes(a.owned) && !state.eager_after.empty()) {
      state.copy_wasted_after.insert(state.eager_after);  // overwritten before anyone read it
      state.eager_after.clear();
    }
    if (writes(a.owned)) state.ghosts_valid = false;  // shared values may have changed
    if (writes(a.ghost)) {
      state.ghosts_valid = true;  // the task defined the ghost values
      state.receivers_hold_sent = false;
    }
  }
  l->sequence = next_sequence_++;
  if (kind == launch_kind::reduction) l->collective_index = next_collective_recorded_++;
  queue_.push_back(l);
  // The data of these copies is final once this launch has run: send it then, not when the
  // next reader is recorded.
  record_ghost_copies(accesses, [&l](const field_access& a, field_state& state) {
    if (!writes(a.owned) || !state.ghosts_read || state.copy_wasted_after.count(l->name)) return false;
    state.eager_after = l->name;
    return true;
  });
  // Scheduling scans the queue, so keep it short: run launches once the window is full.
  if (queue_.size() >= window)
    while (queue_.size() > window / 2)
      if (!progress()) block_until_any_request();
  return l;
}

launch_ptr executor::record_ghost_copy(const std::vector<const field_access*>& fields) {
  data::topology_base* topology = fields.front()->topology;
  std::vector<detail::copied_field> copied;
  const int tag = first_copy_tag + static_cast<int>(ghost_updates_++ % copy_tag_count);
  ghost_copies_ += fields.size();  // field copies; they travel together, one message per peer
  auto l = std::make_shared<launch>();
  l->name = "ghost copy";
  l->kind = launch_kind::ghost_copy;
  for (const field_access* a : fields) {
    field_state& state = fields_[{topology->instance_id(), a->field}];
    add_dependencies(*l, state, region::owned, ro);
    add_dependencies(*l, state, region::ghost, wo);
    if (!state.sent) state.sent = std::make_shared<detail::sent_ghost_values>();
    copied.push_back({a->storage, state.sent, state.receivers_hold_sent});
    state.receivers_hold_sent = true;
    l->name += (copied.size() == 1 ? " " : ", ") + a->storage->name();
  }

  l->start = detail::ghost_copy_start(topology, std::move(copied), tag, &traffic_);

  for (const field_access* a : fields) {
    field_state& state = fields_[{topology->instance_id(), a->field}];
    state.regions[0].readers.push_back(l);
    state.regions[1].last_writer = l;
    state.regions[1].readers.clear();
    state.ghosts_valid = true;
  }
  l->sequence = next_sequence_++;
  queue_.push_back(l);
  return l;
}

launch_ptr executor::record_ghost_reduction(const field_access& a, combine_into_owned combine) {
  if (inside_launch_) throw std::logic_error("executor: reduce_ghosts called from inside a running task");
  auto l = std::make_shared<launch>();
  l->name = "ghost reduction " + a.storage->name();
  l->kind = launch_kind::ghost_reduction;
  field_state& state = fields_[{a.instance, a.field}];
  if (!state.ghosts_valid)
    throw std::logic_error("executor: reduce_ghosts of field '" + a.storage->name() +
                           "': its ghost values are not defined (no task wrote them since its owned values or its "
                           "topology's layout changed)");
  add_dependencies(*l, state, region::ghost, ro);
  add_dependencies(*l, state, region::owned, rw);
  const int tag = first_copy_tag + static_cast<int>(ghost_updates_++ % copy_tag_count);
  l->start = detail::ghost_reduction_start(a.topology, a.storage, std::move(combine), tag, &traffic_);
  state.regions[1].readers.push_back(l);
  state.regions[0].last_writer = l;
  state.regions[0].readers.clear();
  state.ghosts_valid = false;  // the owners' values changed
  l->sequence = next_sequence_++;
  queue_.push_back(l);
  return l;
}

bool executor::ready(launch& l) {
  if (l.state != launch_state::recorded) return false;
  // Collectives start (or are cancelled) in program order, the same on every rank.
  if (l.kind == launch_kind::reduction && l.collective_index != next_collective_started_) return false;
  const launch* failed = nullptr;
  for (auto& d : l.dependencies) {
    if (d->state == launch_state::failed)
      failed = d.get();
    else if (d->state != launch_state::done)
      return false;
  }
  for (auto& d : l.ordered_after)
    if (!d->finished()) return false;
  for (auto& d : l.started)
    if (d->state == launch_state::recorded) return false;
  if (!failed) return true;
  // Cancelled: it never runs, and says which failure it follows.
  if (l.kind == launch_kind::reduction) ++next_collective_started_;
  auto error = std::make_exception_ptr(std::runtime_error(
    "'" + l.name + "' cancelled because '" + failed->failure_origin + "' failed: " + failed->failure_reason));
  l.begin_time = now();
  fail(l, error, failed->failure_origin);
  l.failure_reason = failed->failure_reason;
  return false;
}

void executor::begin(const launch_ptr& launched) {
  launch& l = *launched;
  if (l.kind == launch_kind::reduction) ++next_collective_started_;
  l.state = launch_state::in_flight;
  l.begin_time = now();
  const bool was_inside = inside_launch_;
  inside_launch_ = true;
  try {
    l.start(l);
  } catch (...) {
    inside_launch_ = was_inside;
    ++failures_;
    fail(l, std::current_exception(), l.name);
    l.failure_reason = what_of(l.error);
    if (first_failure_.empty())
      first_failure_ = "'" + l.name + "' failed on rank " + std::to_string(runtime::rank()) + ": " + l.failure_reason;
    unobserved_.push_back(launched);
    return;
  }
  inside_launch_ = was_inside;
  if (l.requests.empty()) complete(l);
}

void executor::note(const launch& l) {
  if (l.kind == launch_kind::task && l.state == launch_state::done) timers::add(l.name, l.end_time - l.begin_time);
  if (tracing_)
    trace_.push_back({l.sequence, l.name, l.state == launch_state::failed ? "failed" : kind_name(l.kind), l.begin_time,
                      l.end_time, l.dependency_sequences});
}

void executor::complete(launch& l) {
  if (l.finish) l.finish();
  l.state = launch_state::done;
  l.end_time = now();
  note(l);
  release(l);
}

void executor::fail(launch& l, std::exception_ptr error, const std::string& origin) {
  l.state = launch_state::failed;
  l.error = std::move(error);
  l.failure_origin = origin;
  l.end_time = now();
  note(l);
  release(l);
}

void executor::release(launch& l) {
  l.dependencies.clear();  // do not keep the history alive
  l.ordered_after.clear();
  l.started.clear();
  l.requests.clear();
  l.start = nullptr;
  l.finish = nullptr;
}

bool executor::complete_arrived_communication() {
  bool completed = false;
  for (auto& l : queue_) {
    // Tasks run to completion in begin(); only communication waits for requests.
    if (l->state != launch_state::in_flight || !l->communicates()) continue;
    int flag = 0;
    MPI_Testall(static_cast<int>(l->requests.size()), l->requests.data(), &flag, MPI_STATUSES_IGNORE);
    if (flag) {
      complete(*l);
      completed = true;
    }
  }
  return completed;
}

bool executor::progress() {
  bool progressed = false;
  // Communication first, so that it overlaps with the tasks that follow.
  for (auto& l : queue_)
    if (l->communicates() && ready(*l)) {
      begin(l);
      progressed = true;
    }
  // Then tasks in program order; stop after one if communication waits to start, so that it
  // starts as soon as its inputs are ready.
  bool communication_waiting = false;
  for (auto& l : queue_) communication_waiting |= l->communicates() && l->state == launch_state::recorded;
  for (auto& l : queue_) {
    if (!l->communicates() && ready(*l)) {
      begin(l);
      progressed = true;
      if (communication_waiting) break;
    }
  }
  progressed |= complete_arrived_communication();
  const auto before = queue_.size();
  queue_.erase(std::remove_if(queue_.begin(), queue_.end(), [](const launch_ptr& l) { return l->finished(); }),
               queue_.end());
  return progressed || queue_.size() != before;
}

bool executor::poll() {
  if (polling_) return false;
  polling_ = true;
  complete_arrived_communication();
  // Safe while a task runs: a ready copy depends on nothing unfinished, and the running task
  // neither writes its owned values (it would wait for the copy) nor reads its ghosts.
  for (auto& l : queue_)
    if (l->communicates() && ready(*l)) begin(l);
  polling_ = false;
  return communication_in_flight();
}

bool executor::communication_in_flight() const {
  return std::any_of(queue_.begin(), queue_.end(),
                     [](const launch_ptr& l) { return l->communicates() && l->state == launch_state::in_flight; });
}

void executor::abort_run() const {
  std::cerr << "flecsi_lite: rank " << runtime::rank() << ": " << first_failure_
            << "; the other ranks wait for this rank's results, so the run is aborted" << std::endl;
  MPI_Abort(runtime::communicator(), 3);
  std::abort();
}

void executor::block_until_any_request() {
  // A rank with a failure cannot count on the others (they may wait for its cancelled messages).
  if (failures_ && runtime::size() > 1) abort_run();
  // Nothing is ready: wait until any request of any launch in flight completes.
  std::vector<MPI_Request> all;
  std::vector<std::pair<launch*, std::size_t>> owner;
  for (auto& l : queue_)
    if (l->state == launch_state::in_flight)
      for (std::size_t i = 0; i < l->requests.size(); ++i) {
        all.push_back(l->requests[i]);
        owner.emplace_back(l.get(), i);
      }
  if (all.empty()) throw std::logic_error("executor: no launch is ready and none is in flight (dependency cycle?)");
  int index = MPI_UNDEFINED;
  MPI_Waitany(static_cast<int>(all.size()), all.data(), &index, MPI_STATUS_IGNORE);
  if (index != MPI_UNDEFINED) owner[index].first->requests[owner[index].second] = all[index];
}

void executor::wait(const launch& target) {
  if (inside_launch_) throw std::logic_error("executor: a running task may not wait for others");
  while (!target.finished())
    if (!progress()) block_until_any_request();
  if (target.state != launch_state::failed) return;
  // Reported through this future: the failure it follows is no longer unobserved.
  unobserved_.erase(
    std::remove_if(unobserved_.begin(), unobserved_.end(),
                   [&target](const launch_ptr& f) { return f->failure_origin == target.failure_origin; }),
    unobserved_.end());
  std::rethrow_exception(target.error);
}

void executor::wait_all() {
  if (inside_launch_) throw std::logic_error("executor: a running task may not wait for others");
  while (!queue_.empty())
    if (!progress()) block_until_any_request();
  if (unobserved_.empty()) return;
  const auto error = unobserved_.front()->error;
  unobserved_.clear();
  std::rethrow_exception(error);
}

void executor::forget_sent_values(std::uint64_t instance, std::size_t field) {
  const auto state = fields_.find({instance, field});
  if (state != fields_.end()) state->second.receivers_hold_sent = false;
}

void executor::before_layout_change(std::uint64_t) { wait_all(); }

void executor::after_layout_change(std::uint64_t topology_id) {
  for (auto& [key, state] : fields_)
    if (key.first == topology_id) {
      state.ghosts_valid = false;
      state.receivers_hold_sent = false;
      state.sent.reset();  // the old layout's values
    }
}

void executor::topology_destroyed(std::uint64_t topology_id) {
  wait_all();
  for (auto it = fields_.begin(); it != fields_.end();)
    it = it->first.first == topology_id ? fields_.erase(it) : std::next(it);
}

}  // namespace flecsi_lite::execution
