#include "flecsi_lite/execution/executor.hh"

#include "flecsi_lite/runtime/context.hh"
#include "flecsi_lite/runtime/runtime.hh"
#include "flecsi_lite/runtime/timers.hh"

#include <algorithm>
#include <fstream>
#include <stdexcept>

namespace flecsi_lite::execution {
namespace {
const char* kind_name(launch_kind k) {
  return k == launch_kind::task ? "task" : k == launch_kind::ghost_copy ? "ghost_copy" : "reduction";
}
// Tags of ghost-copy messages: distinct for copies that may be in flight together.
constexpr int first_copy_tag = 1000, copy_tag_count = 30000;
// Launches recorded ahead of execution before the executor starts running them.
constexpr std::size_t window = 128;
} // namespace

executor& executor::instance() {
  static executor* the_executor = new executor();  // outlives static destructors and MPI
  return *the_executor;
}

executor::executor() : epoch_(std::chrono::steady_clock::now()) {
  data::set_layout_listener(this);
  const std::string trace_file = runtime::current_settings().trace_file;
  tracing_ = !trace_file.empty();
  runtime::at_finalize([this, trace_file] {
    wait_all();
    if (trace_file.empty()) return;
    std::ofstream out;
    if (runtime::rank() == 0) out.open(trace_file);
    write_chrome_trace(trace_, out);
  });
}

executor::~executor() { data::set_layout_listener(nullptr); }

double executor::now() const {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - epoch_).count();
}

void executor::add_dependencies(launch& l, field_state& state, region r, privilege p) {
  region_state& rs = state.regions[static_cast<int>(r)];
  auto depend_on = [&l](const launch_ptr& other) {
    if (other && other->state != launch_state::done) l.dependencies.push_back(other);
  };
  if (p == na) return;
  depend_on(rs.last_writer);  // read after write, write after write
  if (writes(p))
    for (auto& reader : rs.readers) depend_on(reader);  // write after read
}

launch_ptr executor::record(std::string name, launch_kind kind,
                            const std::vector<field_access>& accesses, std::vector<launch_ptr> after,
                            std::function<void(launch&)> start, std::function<void()> finish) {
  if (inside_launch_)
    throw std::logic_error("executor: task '" + name + "' launched from inside a running task");
  auto l = std::make_shared<launch>();
  l->name = std::move(name);
  l->kind = kind;
  l->start = std::move(start);
  l->finish = std::move(finish);
  for (auto& a : after)
    if (a && a->state != launch_state::done) l->dependencies.push_back(a);

  for (const auto& a : accesses) {
    field_state& state = fields_[{a.topology->instance_id(), a.field}];
    if (reads(a.ghost) && !state.ghosts_valid) record_ghost_copy(a, state);
    add_dependencies(*l, state, region::owned, a.owned);
    add_dependencies(*l, state, region::ghost, a.ghost);
  }
  // Update the bookkeeping only after all dependencies are known (a field may appear twice).
  for (const auto& a : accesses) {
    field_state& state = fields_[{a.topology->instance_id(), a.field}];
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
    if (writes(a.owned)) state.ghosts_valid = false;  // shared values may have changed
    if (writes(a.ghost)) state.ghosts_valid = true;   // the task defined the ghost values
  }
  l->sequence = next_sequence_++;
  if (kind == launch_kind::reduction) l->collective_index = next_collective_recorded_++;
  queue_.push_back(l);
  // Scheduling scans the queue, so keep it short: run launches once the window is full.
  if (queue_.size() >= window)
    while (queue_.size() > window / 2)
      if (!progress()) block_until_any_request();
  return l;
}

launch_ptr executor::record_ghost_copy(const field_access& a, field_state& state) {
  data::topology_base* topology = a.topology;
  data::field_storage_base* storage = a.storage;
  const int tag = first_copy_tag + static_cast<int>(ghost_copies_++ % copy_tag_count);
  auto l = std::make_shared<launch>();
  l->name = "ghost copy " + storage->name();
  l->kind = launch_kind::ghost_copy;
  add_dependencies(*l, state, region::owned, ro);
  add_dependencies(*l, state, region::ghost, wo);

  auto receive_buffers = std::make_shared<std::vector<std::vector<std::byte>>>();
  l->start = [topology, storage, tag, receive_buffers](launch& self) {
    const auto& peers = topology->plan().peers;
    const std::size_t bytes = storage->element_size();
    const std::size_t ghost_begin = topology->owned_size();
    const int me = runtime::rank();
    receive_buffers->assign(peers.size(), {});
    // Send buffers must live until the sends complete: keep them with the receive buffers.
    auto send_buffers = std::make_shared<std::vector<std::vector<std::byte>>>(peers.size());
    for (std::size_t p = 0; p < peers.size(); ++p) {
      const auto& peer = peers[p];
      auto& send = (*send_buffers)[p];
      send.resize(peer.send.size() * bytes);
      storage->pack(peer.send.data(), peer.send.size(), send.data());
      if (peer.rank == me) {  // periodic images of this rank's own entities
        storage->unpack(send.data(), ghost_begin + peer.receive_first, peer.receive_count);
        continue;
      }
      auto& receive = (*receive_buffers)[p];
      receive.resize(peer.receive_count * bytes);
      MPI_Request requests[2];
      MPI_Irecv(receive.data(), static_cast<int>(receive.size()), MPI_BYTE, peer.rank, tag,
                runtime::communicator(), &requests[0]);
      MPI_Isend(send.data(), static_cast<int>(send.size()), MPI_BYTE, peer.rank, tag,
                runtime::communicator(), &requests[1]);
      self.requests.insert(self.requests.end(), requests, requests + 2);
    }
    self.finish = [topology, storage, receive_buffers, send_buffers, me] {
      const auto& finished_peers = topology->plan().peers;
      const std::size_t begin = topology->owned_size();
      for (std::size_t p = 0; p < finished_peers.size(); ++p)
        if (finished_peers[p].rank != me)
          storage->unpack((*receive_buffers)[p].data(), begin + finished_peers[p].receive_first,
                          finished_peers[p].receive_count);
    };
  };

  region_state& owned = state.regions[0];
  region_state& ghost = state.regions[1];
  owned.readers.push_back(l);
  ghost.last_writer = l;
  ghost.readers.clear();
  state.ghosts_valid = true;
  l->sequence = next_sequence_++;
  queue_.push_back(l);
  return l;
}

bool executor::ready(const launch& l) const {
  if (l.state != launch_state::recorded) return false;
  for (auto& d : l.dependencies)
    if (d->state != launch_state::done) return false;
  return l.kind != launch_kind::reduction || l.collective_index == next_collective_started_;
}

void executor::begin(launch& l) {
  if (l.kind == launch_kind::reduction) ++next_collective_started_;
  l.state = launch_state::in_flight;
  l.begin_time = now();
  inside_launch_ = true;
  try {
    l.start(l);
  } catch (...) {
    inside_launch_ = false;
    throw;
  }
  inside_launch_ = false;
  if (l.requests.empty()) complete(l);
}

void executor::complete(launch& l) {
  if (l.finish) l.finish();
  l.state = launch_state::done;
  l.end_time = now();
  l.dependencies.clear();  // do not keep the history alive
  l.requests.clear();
  l.start = nullptr;
  l.finish = nullptr;
  if (l.kind == launch_kind::task) timers::add(l.name, l.end_time - l.begin_time);
  if (tracing_) trace_.push_back({l.sequence, l.name, kind_name(l.kind), l.begin_time, l.end_time});
}

bool executor::progress() {
  bool progressed = false;
  // Communication first, so that it overlaps with the tasks that follow.
  for (auto& l : queue_)
    if (l->communicates() && ready(*l)) {
      begin(*l);
      progressed = true;
    }
  // Then tasks in program order; stop after one if communication waits to start, so that it
  // starts as soon as its inputs are ready.
  bool communication_waiting = false;
  for (auto& l : queue_)
    communication_waiting |= l->communicates() && l->state == launch_state::recorded;
  for (auto& l : queue_)
    if (!l->communicates() && ready(*l)) {
      begin(*l);
      progressed = true;
      if (communication_waiting) break;
    }
  for (auto& l : queue_) {
    if (l->state != launch_state::in_flight) continue;
    int flag = 0;
    MPI_Testall(static_cast<int>(l->requests.size()), l->requests.data(), &flag, MPI_STATUSES_IGNORE);
    if (flag) {
      complete(*l);
      progressed = true;
    }
  }
  queue_.erase(std::remove_if(queue_.begin(), queue_.end(),
                              [](const launch_ptr& l) { return l->state == launch_state::done; }),
               queue_.end());
  return progressed;
}

void executor::block_until_any_request() {
  // Nothing is ready: wait until any request of any launch in flight completes.
  std::vector<MPI_Request> all;
  std::vector<std::pair<launch*, std::size_t>> owner;
  for (auto& l : queue_)
    if (l->state == launch_state::in_flight)
      for (std::size_t i = 0; i < l->requests.size(); ++i) {
        all.push_back(l->requests[i]);
        owner.emplace_back(l.get(), i);
      }
  if (all.empty())
    throw std::logic_error("executor: no launch is ready and none is in flight (dependency cycle?)");
  int index = MPI_UNDEFINED;
  MPI_Waitany(static_cast<int>(all.size()), all.data(), &index, MPI_STATUS_IGNORE);
  if (index != MPI_UNDEFINED) owner[index].first->requests[owner[index].second] = all[index];
}

void executor::wait(const launch& target) {
  if (inside_launch_) throw std::logic_error("executor: a running task may not wait for others");
  while (target.state != launch_state::done)
    if (!progress()) block_until_any_request();
}

void executor::wait_all() {
  if (inside_launch_) throw std::logic_error("executor: a running task may not wait for others");
  while (!queue_.empty())
    if (!progress()) block_until_any_request();
}

void executor::before_layout_change(std::uint64_t) { wait_all(); }

void executor::after_layout_change(std::uint64_t topology_id) {
  for (auto& [key, state] : fields_)
    if (key.first == topology_id) state.ghosts_valid = false;
}

void executor::topology_destroyed(std::uint64_t topology_id) {
  wait_all();
  for (auto it = fields_.begin(); it != fields_.end();)
    it = it->first.first == topology_id ? fields_.erase(it) : std::next(it);
}

} // namespace flecsi_lite::execution
