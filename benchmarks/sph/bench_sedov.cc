// Benchmark of the SPH time step on the Sedov-Taylor blast in 3D (apps/sedov, its problem and
// physics keys from sedov_3d.par): the driver's control model runs warm-up steps, then a fixed
// number of timed steps. Prints the wall and CPU time per step, particle-steps per second, the
// neighbour counts, each runtime timer's share of the step, and bytes per particle (fields and
// neighbour lists, besides the local tree).
//   OMP_NUM_THREADS=2 bench_sedov --per-side 50 --steps 10
//   mpirun -np 2 bench_sedov --per-side 100
// benchmarks/sph/run_scaling.sh runs 1 rank x 1 thread, 1 x 2 and 2 x 1 and prints the speed-ups.
#include "nominal_clock.hh"
#include "sedov_problem.hh"

#include "specialization/sph/step/driver.hh"

#include "flecsi_lite/app.hh"
#include "flecsi_lite/runtime.hh"

#include <mpi.h>

#include <sys/resource.h>

#include <algorithm>
#include <cstdio>
#include <ctime>
#include <limits>
#include <string>
#include <vector>

namespace {
using namespace flecsi_lite;
namespace sph = flecsph::sph;
constexpr int D = 3;

struct bench_state : sph::simulation<D> {
  sedov::problem problem;
  long warm_up_steps = 1, timed_steps = 10;
  double clock_ghz = 1;                      ///< the clock the cycles per pair are counted at
  double start = 0, stop = 0;                ///< MPI_Wtime at the end of the warm-up and of the timed steps
  std::clock_t cpu_start = 0, cpu_stop = 0;  ///< CPU time of this process (all its threads), same
  std::uint64_t distributions_before = 0, repeated_searches_before = 0, searches_before = 0;
  std::uint64_t moved_particles_before = 0;
  double moved_bytes_before = 0;
};

/// The keys of the sedov app from `path`, then `overrides`; the benchmark uses the problem and
/// physics keys (its run control and output are its own).
runtime::parameters load_parameters(const std::string& path, const std::vector<std::string>& overrides) {
  runtime::parameter_schema schema;
  sedov::problem_parameters().declare(schema);
  sph::physics_parameters().declare(schema);
  sph::run_parameters({0.05, 0, 0, 0}).declare(schema);
  app::file_parameters().declare(schema);
  return runtime::parameters::load(schema, path, overrides);
}

/// Owned particles with r_ab < 2 h_a (the kernel's neighbours, itself included).
double kernel_neighbours(sph::neighbours_ro<D> neighbours_object, sph::ro_with_ghosts<sph::vector<D>> x,
                         sph::ro<double> h) {
  const sph::neighbourhood<D>& neighbours = *neighbours_object;
  const sph::neighbour_walk<D> walk(neighbours);
  double count = 0;
  for (std::size_t a = 0; a < neighbours.size(); ++a) {
    const double reach = flecsph::physics::kernel_support * h(a);
    sph::vector<D> r;
    const sph::neighbour_row<D> row = walk.row(a);
    for (std::size_t j = 0; j < row.size(); ++j)
      count += row.separation(x(a), x(row.neighbour(j)), j, r) < reach * reach;
  }
  return count;
}

/// Pairs within the reach now, |r_ab| < reach max(h_a, h_b): what a search now would list (the
/// lists, kept over steps with list_skin > 0, hold more).
double within_reach(sph::neighbours_ro<D> neighbours_object, sph::ro_with_ghosts<sph::vector<D>> x,
                    sph::ro_with_ghosts<double> h) {
  const sph::neighbourhood<D>& neighbours = *neighbours_object;
  const sph::neighbour_walk<D> walk(neighbours);
  double count = 0;
  sph::vector<D> r;
  for (std::size_t a = 0; a < neighbours.size(); ++a) {
    const sph::neighbour_row<D> row = walk.row(a);
    for (std::size_t j = 0; j < row.size(); ++j) {
      const std::size_t b = row.neighbour(j);
      const double radius = neighbours.reach * std::max(h(a), h(b));
      count += row.separation(x(a), x(b), j, r) < radius * radius;
    }
  }
  return count;
}

/// The value of option `name`, a whole number of at least 1.
long count_option(const runtime::options& opts, const std::string& name) {
  const std::string text = opts.get(name);
  std::size_t used = 0;
  long value = 0;
  try {
    value = std::stol(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used == 0 || used != text.size() || value < 1)
    throw runtime::parameter_error("bench_sedov: --" + name + " takes a whole number of at least 1, not '" + text +
                                   "'");
  return value;
}

double max_over_ranks(double value) {
  MPI_Allreduce(MPI_IN_PLACE, &value, 1, MPI_DOUBLE, MPI_MAX, runtime::communicator());
  return value;
}

double sum_over_ranks(double value) {
  MPI_Allreduce(MPI_IN_PLACE, &value, 1, MPI_DOUBLE, MPI_SUM, runtime::communicator());
  return value;
}

/// Starts the clock after the warm-up steps, stops it and ends the run after the timed ones (the
/// run ends here, not by max_steps, so that no end-of-run diagnostics fall in the timed steps).
void benchmark_clock(bench_state& s) {
  if (s.step == s.warm_up_steps) {
    flecsi_lite::wait_all();
    MPI_Barrier(runtime::communicator());
    timers::clear();
    s.distributions_before = s.distributions;
    s.repeated_searches_before = s.repeated_searches;
    s.searches_before = s.searches;
    s.moved_particles_before = s.moved_particles;
    s.moved_bytes_before = s.moved_bytes;
    s.start = MPI_Wtime();
    s.cpu_start = std::clock();
  } else if (s.step == s.warm_up_steps + s.timed_steps) {
    flecsi_lite::wait_all();
    MPI_Barrier(runtime::communicator());
    s.stop = MPI_Wtime();
    s.cpu_stop = std::clock();
    s.finished = true;
  }
}

void report(bench_state& s) {
  using f = sph::fields<D>;
  auto& p = *s.particles;
  const double particles = static_cast<double>(p.global_size());
  const double seconds = max_over_ranks(s.stop - s.start);
  const double per_step = seconds / static_cast<double>(s.timed_steps);
  // CPU time shows the work done whatever the load of a shared machine; wall time what it took.
  const double cpu = max_over_ranks(static_cast<double>(s.cpu_stop - s.cpu_start) / CLOCKS_PER_SEC);
  const auto rows = timers::summarize();  // before the measurements below add their own timers
  const double entries = reduce<sph::neighbour_total<D>, reduction::sum>(s.neighbours).get();
  const double in_reach =
    reduce<within_reach, reduction::sum>(s.neighbours, f::position()(p), f::smoothing_length()(p)).get();
  const double in_kernel =
    reduce<kernel_neighbours, reduction::sum>(s.neighbours, f::position()(p), f::smoothing_length()(p)).get();
  const sph::memory_use bytes = sph::measure_memory(s);
  const double field_bytes = max_over_ranks(bytes.fields), list_bytes = max_over_ranks(bytes.neighbour_lists);
  const double tree_bytes = max_over_ranks(static_cast<double>(p.local().bytes()) /
                                           static_cast<double>(std::max<std::size_t>(1, p.owned_size())));
  struct rusage usage {};
  getrusage(RUSAGE_SELF, &usage);
  const double peak_kib = max_over_ranks(static_cast<double>(usage.ru_maxrss));
  // Ghosts (copies of other ranks' particles) per owned particle, as the last distribution left them.
  const double owned = static_cast<double>(p.owned_size()), ghosts = static_cast<double>(p.ghost_size());
  const double ghosts_per_owned = sum_over_ranks(ghosts) / particles;
  const double ghosts_per_owned_max = max_over_ranks(owned > 0 ? ghosts / owned : 0.0);
  if (runtime::rank() != 0) return;
  std::printf("bench_sedov: %lld^3 = %.0f particles, eta %.3g, %d rank(s) x %d thread(s), %ld timed steps after %ld\n",
              static_cast<long long>(s.problem.per_side), particles, s.physics.eta, runtime::size(),
              Kokkos::DefaultHostExecutionSpace().concurrency(), s.timed_steps, s.warm_up_steps);
  std::printf("  wall time per step %.4f s; throughput %.4e particle-steps/s\n", per_step, particles / per_step);
  std::printf("  CPU time per step (largest over ranks, all threads of a rank) %.4f s: %.2f cores busy per rank\n",
              cpu / static_cast<double>(s.timed_steps), cpu / seconds);
  const auto& n = s.neighbours.host();
  std::printf(
    "  neighbours per particle: %.1f within 2 h (kernel), %.1f within the reach %.3g max(h_a, h_b), "
    "%.1f in the lists (searched with reach %.3g max(h_a, h_b): list_skin %.3g)\n",
    in_kernel / particles, in_reach / particles, n.reach, entries / particles, n.list_reach, s.physics.list_skin);
  std::printf(
    "  bytes per owned particle (largest over ranks): %.0f fields + %.0f neighbour lists = %.0f; "
    "besides, %.0f in the local tree and search workspaces\n",
    field_bytes, list_bytes, field_bytes + list_bytes, tree_bytes);
  const auto searches = s.searches - s.searches_before;
  std::printf(
    "  during the timed steps: %llu distributions, %llu repeated searches, %llu neighbour searches "
    "(a list lives %.2f steps)\n",
    static_cast<unsigned long long>(s.distributions - s.distributions_before),
    static_cast<unsigned long long>(s.repeated_searches - s.repeated_searches_before),
    static_cast<unsigned long long>(searches),
    searches ? double(s.timed_steps) / double(searches) : double(s.timed_steps));
  const auto distributions = s.distributions - s.distributions_before;
  const double moved = double(s.moved_particles - s.moved_particles_before),
               moved_bytes = s.moved_bytes - s.moved_bytes_before;
  std::printf(
    "  distribution (%s keys): %.4f ghosts per owned particle (%.4f on the rank with most); per "
    "distribution of the timed steps %.0f particles moved, %.4g bytes (%.4g per particle)\n",
    sph::key_order_names().name(s.physics.key_order).c_str(), ghosts_per_owned, ghosts_per_owned_max,
    distributions ? moved / double(distributions) : 0.0, distributions ? moved_bytes / double(distributions) : 0.0,
    distributions ? moved_bytes / double(distributions) / particles : 0.0);
  std::printf(
    "  time per step by timer (largest over ranks; 'ntree::distribute <phase>' rows are parts of "
    "'ntree::distribute'):\n");
  std::vector<timers::summary_row> sorted(rows.begin(), rows.end());
  std::sort(sorted.begin(), sorted.end(), [](const auto& a, const auto& b) { return a.max > b.max; });
  for (const auto& row : sorted) {
    const double share = row.max / seconds;
    if (share < 0.001) continue;
    std::printf("    %-56s %6ld calls %9.4f s %6.1f%%\n", row.name.c_str(), row.calls,
                row.max / static_cast<double>(s.timed_steps), 100 * share);
  }
  // Cycles per list entry (the target itself included; the density's Newton iterations all in),
  // at the nominal clock: the task's time per step times the cores that ran it.
  const double cores = double(runtime::size()) * double(Kokkos::DefaultHostExecutionSpace().concurrency());
  const auto cycles_per_entry = [&](const char* timer) {
    for (const auto& row : rows)
      if (row.name == timer) return row.max / double(s.timed_steps) * s.clock_ghz * 1e9 * cores / entries;
    return 0.0;
  };
  std::printf(
    "  cycles per list entry at %.2f GHz (x %.0f cores): forces %.1f, density %.1f; search and refit %.4f s "
    "per step\n",
    s.clock_ghz, cores, cycles_per_entry("sph::compute_forces"), cycles_per_entry("sph::compute_density"), [&] {
      double t = 0;
      for (const auto& row : rows)
        if (row.name == "sph::search_neighbours" || row.name == "ntree::refit") t += row.max;
      return t / double(s.timed_steps);
    }());
  std::printf(
    "  peak resident memory %.0f MiB per rank: %.0f bytes per owned particle (the libraries' own "
    "memory included)\n",
    peak_kib / 1024.0, peak_kib * 1024.0 / (particles / double(runtime::size())));
  std::printf("throughput: %.4e particle-steps/s\n", particles / per_step);
}
}  // namespace

int main(int argc, char** argv) {
  runtime::options options(
    "The SPH step on the 3D Sedov-Taylor blast: time per step, throughput, neighbours, "
    "time per task, bytes per particle.");
  options.value("per-side", "N", "lattice particles per side (N^3 particles)", "50")
    .value("steps", "S", "timed steps", "10")
    .value("warm-up", "W", "steps before the timed ones (the first distributes the lattice)", "1")
    .value("eta", "ETA", "h = eta (m/rho)^(1/3): 1.42 gives 93 neighbours within 2h on the lattice", "1.42")
    .value("parameters", "FILE", "sedov parameter file whose problem and physics keys are used",
           FLECSPH_SEDOV_3D_PARAMETERS)
    .value("clock-ghz", "GHZ", "clock of the cycles per pair (0: the cpu MHz of /proc/cpuinfo)", "0")
    .repeated("set", "KEY=VALUE", "override a problem or physics key (after --per-side and --eta)");
  runtime::runtime rt(argc, argv, options);
  if (!rt.proceed()) return rt.exit_code();
  try {
    bench_state s;
    s.warm_up_steps = count_option(rt.opts(), "warm-up");
    s.timed_steps = count_option(rt.opts(), "steps");
    s.clock_ghz = flecsph::benchmarks::nominal_clock_ghz(std::stod(rt.opts().get("clock-ghz")));
    std::vector<std::string> overrides{"particles_per_side=" + rt.opts().get("per-side"),
                                       "eta=" + rt.opts().get("eta")};
    for (const auto& extra : rt.opts().all("set")) overrides.push_back(extra);
    const auto p = load_parameters(rt.opts().get("parameters"), overrides);
    s.problem = sedov::problem_parameters().read(p);
    if (s.problem.dimension != D) throw runtime::parameter_error("bench_sedov: dimension must be 3");
    s.physics = sph::physics_parameters().read(p);
    s.run.end_time = std::numeric_limits<double>::max();
    s.run.progress_every = 0;
    s.run.diagnostics_every = 0;

    auto m = sph::make_control_model<bench_state>();
    m.action("initial_data", "lattice", [](bench_state& state) { sedov::create_lattice(state, state.problem); });
    m.action("output", "benchmark_clock", benchmark_clock);
    m.action("finalize", "report", report);
    const int status = m.execute(s);
    timers::clear();  // reported above
    return status;
  } catch (const runtime::parameter_error& e) {  // exit status 2, as the apps
    log::error() << e.what();
    return 2;
  }
}
