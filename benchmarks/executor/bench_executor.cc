// Benchmarks of the execution model, reported as ratios measured in one run:
//  1. cost of a task launch through the executor vs a direct call of the same function;
//  2. ghost-copy throughput through the executor vs hand-written non-blocking MPI moving the
//     same bytes between the same ranks.
//   mpirun -np 2 bench_executor [--launches N] [--halo H] [--copies R]
#include "flecsi_lite/data.hh"
#include "flecsi_lite/execution.hh"
#include "flecsi_lite/runtime.hh"
#include "flecsi_lite/topology/narray.hh"

#include <chrono>
#include <cstdio>

using namespace flecsi_lite;
using topology::narray;

namespace {
const field<double>::definition<narray> counter{"counter"};
const field<double>::definition<narray> halo_field{"halo_field"};

void increment(field<double>::accessor<rw> c) { c(0) += 1; }
void touch_owned(field<double>::accessor<rw> f) { f(0) += 1; }
double read_ghost(field<double>::accessor<ro, ro> f) { return f(f.size() - 1); }

double seconds_since(std::chrono::steady_clock::time_point t) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t).count();
}

void launch_overhead(long launches) {
  narray n(1024 * runtime::size(), 0, false);
  execute<increment>(counter(n));
  wait_all();
  // Direct calls of the same task on a prepared accessor.
  auto direct = counter(n).make_accessor<rw, na>();
  auto t0 = std::chrono::steady_clock::now();
  for (long i = 0; i < launches; ++i) increment(direct);
  const double direct_time = seconds_since(t0);
  // Through the executor, queued (each launch depends on the previous: read-write chain).
  t0 = std::chrono::steady_clock::now();
  for (long i = 0; i < launches; ++i) execute<increment>(counter(n));
  wait_all();
  const double queued_time = seconds_since(t0);
  // Through the executor, waiting for each one.
  t0 = std::chrono::steady_clock::now();
  for (long i = 0; i < launches; ++i) execute<increment>(counter(n)).wait();
  const double synchronous_time = seconds_since(t0);
  if (runtime::rank() == 0) {
    std::printf("task launch (%ld launches of a one-element task)\n", launches);
    std::printf("  direct call          %10.1f ns per call\n", 1e9 * direct_time / launches);
    std::printf("  execute, queued      %10.1f ns per launch   ratio to direct %8.1f\n", 1e9 * queued_time / launches,
                queued_time / direct_time);
    std::printf("  execute + wait       %10.1f ns per launch   ratio to direct %8.1f\n",
                1e9 * synchronous_time / launches, synchronous_time / direct_time);
  }
}

void ghost_copy_throughput(std::size_t halo, int copies) {
  const int size = runtime::size(), rank = runtime::rank();
  narray n(4 * halo * size, halo, true);
  execute<touch_owned>(halo_field(n));
  execute<read_ghost>(halo_field(n));
  wait_all();
  const auto start_copies = execution::executor::instance().ghost_copies_started();
  auto t0 = std::chrono::steady_clock::now();
  for (int i = 0; i < copies; ++i) {
    execute<touch_owned>(halo_field(n));  // ghosts stale
    execute<read_ghost>(halo_field(n));   // one ghost copy
  }
  wait_all();
  const double framework_time = seconds_since(t0);
  const auto performed = execution::executor::instance().ghost_copies_started() - start_copies;

  // Hand-written: pack the same entities, exchange with Isend/Irecv, unpack.
  const auto& plan = n.plan();
  auto values = halo_field(n).storage().view();
  std::vector<std::vector<double>> send(plan.peers.size()), receive(plan.peers.size());
  MPI_Barrier(runtime::communicator());
  t0 = std::chrono::steady_clock::now();
  for (int i = 0; i < copies; ++i) {
    values(0) += 1;
    std::vector<MPI_Request> requests;
    for (std::size_t p = 0; p < plan.peers.size(); ++p) {
      const auto& peer = plan.peers[p];
      send[p].resize(peer.send.size());
      receive[p].resize(peer.receive_count);
      for (std::size_t k = 0; k < peer.send.size(); ++k) send[p][k] = values(peer.send[k]);
      if (peer.rank == rank) {
        std::copy(send[p].begin(), send[p].end(), values.data() + n.owned_size() + peer.receive_first);
        continue;
      }
      requests.resize(requests.size() + 2);
      MPI_Irecv(receive[p].data(), int(peer.receive_count), MPI_DOUBLE, peer.rank, 7, runtime::communicator(),
                &requests[requests.size() - 2]);
      MPI_Isend(send[p].data(), int(send[p].size()), MPI_DOUBLE, peer.rank, 7, runtime::communicator(),
                &requests.back());
    }
    MPI_Waitall(int(requests.size()), requests.data(), MPI_STATUSES_IGNORE);
    for (std::size_t p = 0; p < plan.peers.size(); ++p)
      if (plan.peers[p].rank != rank)
        std::copy(receive[p].begin(), receive[p].end(), values.data() + n.owned_size() + plan.peers[p].receive_first);
  }
  const double manual_time = seconds_since(t0);
  const double bytes = 2.0 * halo * sizeof(double) * copies;  // received per rank
  if (rank == 0) {
    std::printf("ghost copy (%zu entities per side, %d copies, %d rank(s), %llu copies performed)\n", halo, copies,
                size, static_cast<unsigned long long>(performed));
    std::printf("  hand-written MPI     %10.1f MB/s per rank\n", bytes / manual_time / 1e6);
    std::printf("  executor             %10.1f MB/s per rank   time ratio to hand-written %6.2f\n",
                bytes / framework_time / 1e6, framework_time / manual_time);
  }
}
}  // namespace

int main(int argc, char** argv) {
  runtime::options options("Executor benchmarks: launch overhead and ghost-copy throughput.");
  options.value("launches", "N", "task launches to time", "200000")
    .value("halo", "H", "ghost entities per side for the copy benchmark", "200000")
    .value("copies", "R", "ghost copies to time", "200");
  runtime::runtime rt(argc, argv, options);
  if (!rt.proceed()) return rt.exit_code();
  launch_overhead(std::stol(rt.opts().get("launches")));
  ghost_copy_throughput(std::stoul(rt.opts().get("halo")), std::stoi(rt.opts().get("copies")));
  return 0;
}
