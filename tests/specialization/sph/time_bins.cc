// Individual time steps (time_bins.hh): the bin arithmetic of the timeline; on a hot spot in a
// cold medium, that particles in very different bins get exactly the kicks their own steps say
// (each kick half its own step times its own accelerations, an inactive particle's accelerations
// untouched, every particle's steps tiling the timeline), and that the limiter keeps every
// inactive particle's bin within log2(time_step_limiter) of the bins of the particles near it
// that start a step, by waking it (checked by a direct search over all pairs; without the
// limiter, particles far above such neighbours remain).
#include "sph_setup.hh"

#include <catch2/catch.hpp>

#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <map>

namespace {
using namespace sph_test;
constexpr int D = 2;
using f = sph::fields<D>;
using sph::timeline;

TEST_CASE("bins of a step and their alignment", "[time_bins]") {
  const double tick = std::ldexp(1.0, -timeline::bins);  // a span of 1
  CHECK(sph::bin_of_step(tick, tick, timeline::bins) == 0);
  CHECK(sph::bin_of_step(0.99 * tick, tick, timeline::bins) == -1);
  CHECK(sph::bin_of_step(std::nan(""), tick, timeline::bins) == -1);
  CHECK(sph::bin_of_step(0.25, tick, timeline::bins) == timeline::bins - 2);
  CHECK(sph::bin_of_step(0.2499999, tick, timeline::bins) == timeline::bins - 3);
  CHECK(sph::bin_of_step(std::numeric_limits<double>::infinity(), tick, timeline::bins) == timeline::bins);
  CHECK(sph::bin_of_step(0.9, tick, 12) == 12);
  for (int bin = 0; bin <= timeline::bins; ++bin) {
    CHECK(sph::bin_of_step(std::ldexp(tick, bin), tick, timeline::bins) == bin);
    CHECK(sph::bin_of_step(std::ldexp(tick, bin) * (1 - 1e-15), tick, timeline::bins) == bin - 1);
  }
  CHECK(sph::aligned_bin(10, 0) == 10);
  CHECK(sph::aligned_bin(10, 3 * 64) == 6);
  CHECK(sph::aligned_bin(3, 3 * 64) == 3);
  CHECK(sph::aligned_bin(5, 1) == 0);
  const auto t = timeline::spanning(0.0, 0.3);
  CHECK(t.time_at(timeline::span, 0.3) == 0.3);
  CHECK(t.time_at(timeline::span / 2, 0.3) == 0.15);
}

/// A cold medium at rest with a hot spot at the centre (u 1e6 times higher): its particles take
/// steps thousands of times shorter than the cold ones far away.
struct hot_spot : sph::simulation<D> {
  explicit hot_spot(int limiter) {
    physics.time_steps.stepping = sph::time_stepping::individual;
    physics.time_steps.limiter = limiter;
    run.end_time = 1.0;
    load_lattice(*this, {24, true, 1.0, 1e-6, 0.0, 0.0, 0.0});
    auto& p = *particles;
    {
      const auto x = flecsi_lite::host_view(f::position()(p));
      const auto u = flecsi_lite::host_view(f::internal_energy(p));
      for (std::size_t a = 0; a < p.owned_size(); ++a)
        if (std::hypot(x(a)[0] - 0.5, x(a)[1] - 0.5) < 0.08) u(a) = 1.0;
    }
    sph::start_timeline(*this);
    sph::update_neighbours(*this, true);
    sph::update_density(*this);
    sph::update_pressure(*this);
    sph::update_forces(*this);
    sph::choose_time_step(*this, false);
  }
};

/// What a particle's current step started from, and what its steps added up to.
struct record {
  sph::vector<D> v{}, a{};
  double u = 0, du = 0;
  std::int64_t begin = 0, length = 0, tiled = 0;
  long kicks = 0;
};

TEST_CASE("each particle is kicked by its own step, inactive ones are left alone", "[time_bins][mpi]") {
  hot_spot s(0);
  auto& p = *s.particles;
  std::map<std::uint64_t, record> records;  // by id: the distribution may move particles
  int widest_spread = 0;
  for (int step = 0; step < 40; ++step) {
    {  // the steps starting now: their initial state
      const auto id = flecsi_lite::host_view(f::id()(p));
      const auto v = flecsi_lite::host_view(f::velocity(p));
      const auto a = flecsi_lite::host_view(f::acceleration(p));
      const auto u = flecsi_lite::host_view(f::internal_energy(p));
      const auto du = flecsi_lite::host_view(f::internal_energy_rate(p));
      const auto begin = flecsi_lite::host_view(f::step_begin(p));
      const auto end = flecsi_lite::host_view(f::step_end(p));
      const auto bin = flecsi_lite::host_view(f::time_bin(p));
      int smallest = timeline::bins, largest = 0;
      for (std::size_t i = 0; i < p.owned_size(); ++i) {
        smallest = std::min(smallest, bin(i));
        largest = std::max(largest, bin(i));
        REQUIRE(begin(i) % timeline::ticks_of(bin(i)) == 0);       // aligned
        REQUIRE(end(i) - begin(i) == timeline::ticks_of(bin(i)));  // no limiter: nobody is woken
        if (begin(i) != s.clock.now) continue;
        const bool known = records.count(id(i)) > 0;
        record& r = records[id(i)];
        if (known || step == 0)
          REQUIRE(r.tiled == begin(i));  // the steps so far tile the timeline from 0
        else
          r.tiled = begin(i);  // arrived from another rank in a distribution
        r.v = v(i), r.a = a(i), r.u = u(i), r.du = du(i), r.begin = begin(i), r.length = end(i) - begin(i);
      }
      widest_spread = std::max(widest_spread, largest - smallest);
    }
    sph::first_kick_and_drift(s);
    sph::update_neighbours(s);
    sph::update_density(s);
    sph::update_pressure(s);
    sph::update_forces(s);
    sph::second_kick(s);
    {
      const auto id = flecsi_lite::host_view(f::id()(p));
      const auto v = flecsi_lite::host_view(f::velocity(p));
      const auto a = flecsi_lite::host_view(f::acceleration(p));
      const auto u = flecsi_lite::host_view(f::internal_energy(p));
      const auto du = flecsi_lite::host_view(f::internal_energy_rate(p));
      const auto end = flecsi_lite::host_view(f::step_end(p));
      for (std::size_t i = 0; i < p.owned_size(); ++i) {
        const auto found = records.find(id(i));
        if (found == records.end()) {  // arrived in this step's distribution, in mid-step
          REQUIRE(flecsi_lite::runtime::size() > 1);
          continue;
        }
        record& r = found->second;
        if (end(i) != s.clock.next) {  // inactive: its forces were not recomputed
          for (int k = 0; k < D; ++k) REQUIRE(a(i)[k] == r.a[k]);
          REQUIRE(du(i) == r.du);
          continue;
        }
        const double half = 0.5 * s.clock.duration(r.length);
        for (int k = 0; k < D; ++k) REQUIRE(v(i)[k] == (r.v[k] + half * r.a[k]) + half * a(i)[k]);
        REQUIRE(u(i) == (r.u + half * r.du) + half * du(i));
        r.tiled += r.length;
        ++r.kicks;
      }
    }
    sph::choose_time_step(s, true);
  }
  INFO(s.distributions << " distributions");
  INFO("widest spread of bins " << widest_spread);
  CHECK(widest_spread >= 6);  // steps 64 times apart and more
  long fewest = std::numeric_limits<long>::max(), most = 0;
  for (const auto& [id, r] : records) fewest = std::min(fewest, r.kicks), most = std::max(most, r.kicks);
  INFO("kicks per particle on this rank: " << fewest << " to " << most);
  CHECK(most >= 30);   // the hottest particles are active in (nearly) every system step
  CHECK(fewest <= 1);  // the far cold medium at most once in those 40
}

/// Every rank's values of field `field` in rank order (x, h, bins of all particles).
template<class T, class Field>
std::vector<T> gathered(hot_spot& s, const Field& field) {
  auto& p = *s.particles;
  const auto view = flecsi_lite::host_view(field(p));
  std::vector<T> local(view.data(), view.data() + p.owned_size());
  const MPI_Comm comm = flecsi_lite::runtime::communicator();
  const int ranks = flecsi_lite::runtime::size();
  int bytes = static_cast<int>(local.size() * sizeof(T));
  std::vector<int> counts(ranks), offsets(ranks);
  MPI_Allgather(&bytes, 1, MPI_INT, counts.data(), 1, MPI_INT, comm);
  int total = 0;
  for (int r = 0; r < ranks; ++r) offsets[r] = total, total += counts[r];
  std::vector<T> all(total / sizeof(T));
  MPI_Allgatherv(local.data(), bytes, MPI_BYTE, all.data(), counts.data(), offsets.data(), MPI_BYTE, comm);
  return all;
}

/// Inactive particles whose bin exceeds by more than `levels` the bin of a particle within
/// 2 max(h) that just started a step (by direct search over all pairs, all ranks).
long limiter_violations(hot_spot& s, int levels) {
  const auto x = gathered<sph::vector<D>>(s, f::position());
  const auto h = gathered<double>(s, f::smoothing_length());
  const auto bin = gathered<std::int32_t>(s, f::time_bin);
  const auto begin = gathered<std::int64_t>(s, f::step_begin);
  long count = 0;
  for (std::size_t b = 0; b < x.size(); ++b) {
    if (begin[b] == s.clock.now) continue;
    for (std::size_t a = 0; a < x.size(); ++a) {
      if (begin[a] != s.clock.now) continue;
      const double reach = 2 * std::max(h[a], h[b]);
      if (norm<D>(image_separation<D>(x[a], x[b], true)) < reach && bin[b] > bin[a] + levels) {
        ++count;
        break;
      }
    }
  }
  return count;
}

TEST_CASE("the limiter wakes particles far above their neighbours' bins", "[time_bins][mpi]") {
  for (const int limiter : {4, 0}) {
    hot_spot s(limiter);
    long violations = limiter_violations(s, 2);
    for (int step = 0; step < 30; ++step) {
      sph::first_kick_and_drift(s);
      sph::update_neighbours(s);
      sph::update_density(s);
      sph::update_pressure(s);
      sph::update_forces(s);
      sph::second_kick(s);
      sph::choose_time_step(s, true);
      violations += limiter_violations(s, 2);
    }
    const long all = violations;  // every rank counted all particles
    INFO("limiter " << limiter << ": " << all << " inactive particles above a starting neighbour's bin + 2, " << s.woken
                    << " woken");
    if (limiter == 4) {
      CHECK(all == 0);
      CHECK(s.woken > 0);
    } else {
      CHECK(all > 0);
      CHECK(s.woken == 0);
    }
  }
}

}  // namespace
