// Neighbour lists kept over several steps (list_reuse.hh), on 1 and 2 ranks: through steps in
// which the lists are kept, their entries within reach now are those of a search at the current
// positions entry for entry, in order; every density equals the direct sum over all particles; the
// decision to search again is the same on every rank; a kept list made stale on purpose is caught
// both by the check and by the comparison (so the comparison would see a missed neighbour). The
// decisions and the final state are written for mpi.sph_list_reuse.compare (1 against 2 ranks).
#include "sph_setup.hh"

#include <catch2/catch.hpp>

#include <mpi.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

namespace {
using namespace sph_test;
constexpr int D = 2;
using f = sph::fields<D>;

/// A jittered lattice with random velocities fast enough that the particles use the list skin up
/// within a few steps; in an open box (`periodic` false), where no particle crosses a periodic
/// boundary (which makes the lists searched again: see the last test cases).
struct reuse_run : sph::simulation<D> {
  reuse_run(double list_skin, bool is_periodic) : periodic(is_periodic) {
    physics.list_skin = list_skin;
    physics.conductivity = 0;
    run.end_time = 1.0;
    load_lattice(*this, {24, periodic, 1.0, 1.0, 0.25, 0.6, 0.1});
    sph::update_neighbours(*this, true);
    sph::update_density(*this);
    sph::update_pressure(*this);
    sph::update_forces(*this);
    sph::choose_time_step(*this, false);
  }
  /// One kick-drift-kick step, the driver's order (sph_model.hh); after the search, `check`.
  template<class Check>
  void step(Check&& check) {
    sph::first_kick_and_drift(*this);
    sph::update_neighbours(*this);
    check();
    sph::update_density(*this);
    sph::update_pressure(*this);
    sph::update_forces(*this);
    sph::second_kick(*this);
    sph::choose_time_step(*this, true);
  }
  bool periodic;
};

/// Every rank's values of `local` gathered on every rank, in rank order.
template<class T>
std::vector<T> all_gather(const std::vector<T>& local, MPI_Datatype type) {
  const MPI_Comm comm = flecsi_lite::runtime::communicator();
  const int ranks = flecsi_lite::runtime::size();
  int count = static_cast<int>(local.size());
  std::vector<int> counts(ranks), offsets(ranks);
  MPI_Allgather(&count, 1, MPI_INT, counts.data(), 1, MPI_INT, comm);
  int total = 0;
  for (int r = 0; r < ranks; ++r) offsets[r] = total, total += counts[r];
  std::vector<T> all(total);
  MPI_Allgatherv(local.data(), count, type, all.data(), counts.data(), offsets.data(), type, comm);
  return all;
}

/// Entries (row by row) where the lists of `s`, less their entries beyond the reach now, differ
/// from those of a search now; 0 when equal. The entries are kept by the search's own pair
/// criterion (image x_b + shift, squared distance summed axis by axis, max of the squared radii).
std::size_t differences_from_a_search_now(reuse_run& s) {
  auto& p = *s.particles;
  sph::tracked_neighbourhood<D> fresh{"fresh lists"};
  p.refresh_local_tree();  // also copies the ghosts' current values
  sph::find_neighbours(p, fresh, 0.0);
  const auto& n = s.neighbours.host();
  const sph::neighbour_walk<D> kept(n), now(fresh.host());
  REQUIRE(n.size() == fresh.host().size());
  const auto x = flecsi_lite::host_view(f::position()(p));
  const auto h = flecsi_lite::host_view(f::smoothing_length()(p));
  std::size_t differences = 0;
  for (std::size_t a = 0; a < n.size(); ++a) {
    std::vector<std::uint32_t> mine;
    const sph::neighbour_row<D> row = kept.row(a);
    for (std::size_t j = 0; j < row.size(); ++j) {
      const std::uint32_t entry = row.entries[j];
      const std::size_t b = row.neighbour(j);
      const auto& shift = row.shift(j);
      double r2 = 0;
      for (int k = 0; k < D; ++k) {
        const double d = x(a)[k] - (x(b)[k] + shift[k]);
        r2 += d * d;
      }
      const double radius_a = n.reach * h(a), radius_b = n.reach * h(b);
      if (r2 < std::max(radius_a * radius_a, radius_b * radius_b)) mine.push_back(entry);
    }
    const sph::neighbour_row<D> searched = now.row(a);  // reuses the buffer of `row`, copied into mine
    const std::vector<std::uint32_t> theirs(searched.entries, searched.entries + searched.size());
    if (mine != theirs) differences += std::max(mine.size(), theirs.size());
  }
  return differences;
}

/// The largest relative difference between a density and the direct sum over every particle of
/// every rank (nearest periodic image if periodic) at its h.
double worst_density_error(reuse_run& s) {
  auto& p = *s.particles;
  const std::size_t owned = p.owned_size();
  const auto x = flecsi_lite::host_view(f::position()(p));
  const auto m = flecsi_lite::host_view(f::mass()(p));
  const auto h = flecsi_lite::host_view(f::smoothing_length()(p));
  const auto rho = flecsi_lite::host_view(f::density(p));
  std::vector<double> mine;
  for (std::size_t b = 0; b < owned; ++b) {
    for (int k = 0; k < D; ++k) mine.push_back(x(b)[k]);
    mine.push_back(m(b));
  }
  const auto all = all_gather(mine, MPI_DOUBLE);
  double worst = 0;
  for (std::size_t a = 0; a < owned; ++a) {
    double direct = 0;
    for (std::size_t i = 0; i < all.size(); i += D + 1) {
      const sph::vector<D> x_b{all[i], all[i + 1]};
      direct += all[i + D] *
                flecsph::physics::cubic_spline<D>::value(norm<D>(image_separation<D>(x(a), x_b, s.periodic)), h(a));
    }
    worst = std::max(worst, std::fabs(rho(a) - direct) / direct);
  }
  MPI_Allreduce(MPI_IN_PLACE, &worst, 1, MPI_DOUBLE, MPI_MAX, flecsi_lite::runtime::communicator());
  return worst;
}

bool same_on_every_rank(int value) {
  int low = value, high = value;
  MPI_Allreduce(MPI_IN_PLACE, &low, 1, MPI_INT, MPI_MIN, flecsi_lite::runtime::communicator());
  MPI_Allreduce(MPI_IN_PLACE, &high, 1, MPI_INT, MPI_MAX, flecsi_lite::runtime::communicator());
  return low == high;
}

/// Every particle's id x v u h rho in hexadecimal floats, a line per particle by id, on rank 0.
std::vector<std::string> state_lines(reuse_run& s) {
  auto& p = *s.particles;
  const auto id = flecsi_lite::host_view(f::id()(p));
  const auto x = flecsi_lite::host_view(f::position()(p));
  const auto v = flecsi_lite::host_view(f::velocity(p));
  const auto u = flecsi_lite::host_view(f::internal_energy(p));
  const auto h = flecsi_lite::host_view(f::smoothing_length()(p));
  const auto rho = flecsi_lite::host_view(f::density(p));
  constexpr int columns = 1 + 2 * D + 3;
  std::vector<double> mine;
  for (std::size_t i = 0; i < p.owned_size(); ++i) {
    mine.push_back(double(id(i)));
    for (int k = 0; k < D; ++k) mine.push_back(x(i)[k]);
    for (int k = 0; k < D; ++k) mine.push_back(v(i)[k]);
    mine.insert(mine.end(), {u(i), h(i), rho(i)});
  }
  const auto all = all_gather(mine, MPI_DOUBLE);
  std::vector<std::array<double, columns>> rows(all.size() / columns);
  for (std::size_t r = 0; r < rows.size(); ++r) std::copy_n(&all[r * columns], columns, rows[r].begin());
  std::sort(rows.begin(), rows.end(), [](const auto& l, const auto& r) { return l[0] < r[0]; });
  std::vector<std::string> lines;
  char field[32];
  for (const auto& row : rows) {
    std::string line;
    for (double value : row) {
      std::snprintf(field, sizeof field, "%a ", value);
      line += field;
    }
    lines.push_back(line);
  }
  return lines;
}
/// The slack of the kept lists of `s` now (collective).
sph::list_slack list_slack_now(reuse_run& s) {
  auto& p = *s.particles;
  return flecsi_lite::reduce<sph::measure_neighbour_slack<D>, sph::neighbour_slack_reduction>(
           s.neighbours, p.space(), f::position()(p), f::smoothing_length()(p), f::drift(p), f::distributed_h(p))
    .get()
    .lists;
}
}  // namespace

TEST_CASE("lists kept over steps are those of a search now; densities are the direct sums", "[sph][list_reuse]") {
  reuse_run s(0.15, false);
  std::string decisions;
  long kept_steps = 0;
  for (int n = 0; n < 16; ++n) {
    const auto searches = s.searches;
    s.step([&] {
      const bool searched = s.searches != searches;
      kept_steps += !searched;
      decisions += searched ? 'S' : 'k';
      CHECK(same_on_every_rank(searched));
      CHECK(differences_from_a_search_now(s) == 0);
    });
    CHECK(worst_density_error(s) < 1e-12);
  }
  // The test exercised both: lists kept over steps, and searches when the skin was used up.
  CHECK(kept_steps >= 4);
  CHECK(kept_steps <= 14);
  const auto lines = state_lines(s);
  if (flecsi_lite::runtime::rank() == 0) {
    std::ofstream out("list_reuse_state." + std::to_string(flecsi_lite::runtime::size()) + ".txt");
    out << decisions << "\n";
    for (const auto& line : lines) out << line << "\n";
    REQUIRE(out.good());
  }
}

TEST_CASE("a particle that crossed a periodic boundary makes the lists searched again", "[sph][list_reuse]") {
  reuse_run s(0.15, true);
  auto& p = *s.particles;
  CHECK(sph::lists_still_suffice(list_slack_now(s), p.settings().support, s.physics.list_skin));
  {
    // The particle nearest x = 0 steps across it by 1e-6: its image shifts in the lists are stale.
    auto x = flecsi_lite::host_view(f::position()(p));
    std::size_t nearest = 0;
    for (std::size_t a = 0; a < p.owned_size(); ++a)
      if (x(a)[0] < x(nearest)[0]) nearest = a;
    if (p.owned_size() > 0 && x(nearest)[0] < 1.0 / 24) x(nearest)[0] += 1.0 - x(nearest)[0] - 1e-6;
  }
  const auto slack = list_slack_now(s);
  CHECK(slack.displacement == std::numeric_limits<double>::infinity());
  CHECK_FALSE(sph::lists_still_suffice(slack, p.settings().support, s.physics.list_skin));
}

TEST_CASE("a kept list made stale is caught by the check and by the comparison", "[sph][list_reuse]") {
  reuse_run s(0.15, false);
  s.step([] {});
  // Move every particle by a quarter of its h along x (beyond the skin: 2 * 0.25 > 0.15 * 2.1),
  // without searching: the kept lists miss pairs that came within reach.
  auto& p = *s.particles;
  {
    auto x = flecsi_lite::host_view(f::position()(p));
    const auto h = flecsi_lite::host_view(f::smoothing_length()(p));
    for (std::size_t a = 0; a < p.owned_size(); ++a) x(a)[0] += (a % 2 ? 0.25 : -0.25) * h(a);
  }
  const auto slack = list_slack_now(s);
  CHECK(slack.displacement >= 0.25 * (1 - 1e-12));
  CHECK_FALSE(sph::lists_still_suffice(slack, p.settings().support, s.physics.list_skin));
  long missed = static_cast<long>(differences_from_a_search_now(s));
  MPI_Allreduce(MPI_IN_PLACE, &missed, 1, MPI_LONG, MPI_SUM, flecsi_lite::runtime::communicator());
  CHECK(missed > 0);
}

TEST_CASE("the lists suffice exactly while 2 displacement + reach growth stays within the skin", "[sph][list_reuse]") {
  const double reach = 2.1, skin = 0.2;
  CHECK(sph::lists_still_suffice({0, 1}, reach, skin));
  CHECK(sph::lists_still_suffice({0.2, 1.0}, reach, skin));  // 0.4 + 2.1 <= 2.52
  CHECK_FALSE(sph::lists_still_suffice({0.22, 1.0}, reach, skin));
  CHECK(sph::lists_still_suffice({0, 1.19}, reach, skin));
  CHECK_FALSE(sph::lists_still_suffice({0, 1.21}, reach, skin));
  CHECK(sph::lists_still_suffice({0, 0.5}, reach, 0.0));  // h shrank, nothing moved
  CHECK_FALSE(sph::lists_still_suffice({1e-9, 1.0}, reach, 0.0));
}
