// Short runs of the SPH driver's control model: a periodic box of gas in random motion conserves
// momentum to round-off, mass exactly and energy to the leapfrog's accuracy (which improves as
// dt^2); fixed wall particles do not move and the impulse they take balances the fluid's momentum.
#include "sph_setup.hh"

#include <catch2/catch.hpp>

#include <cmath>

namespace {
using namespace sph_test;

template<int D>
struct box_run : sph::simulation<D> {
  lattice shape;
};

template<int D>
sph::conserved_totals<D> run_box(double courant, double end_time, long steps, box_run<D>& s) {
  s.physics.courant = courant;
  s.physics.eos.ideal.gamma = 1.4;
  s.run.end_time = end_time;
  s.run.max_steps = steps;
  s.run.progress_every = 0;
  s.run.diagnostics_every = 0;
  auto m = sph::make_control_model<box_run<D>>();
  m.action("initial_data", "lattice", [](box_run<D>& state) { load_lattice(state, state.shape); });
  m.run(s);
  return s.totals;
}
}  // namespace

TEST_CASE("a short run conserves mass exactly, momentum to round-off, energy to O(dt^2)", "[sph][integration]") {
  const lattice shape{12, true, 1.0, 1.0, 0.2, 0.3, 0.3};
  box_run<2> coarse, fine;
  coarse.shape = fine.shape = shape;
  const auto end_coarse = run_box<2>(0.3, 1.0, 20, coarse);
  CHECK(coarse.step == 20);
  CHECK(end_coarse.mass == coarse.initial_totals.mass);
  for (int k = 0; k < 2; ++k) CHECK(std::fabs(end_coarse.momentum[k] - coarse.initial_totals.momentum[k]) < 1e-15);
  const double error_coarse = std::fabs(end_coarse.total - coarse.initial_totals.total) / coarse.initial_totals.total;
  CHECK(error_coarse < 1e-4);
  CHECK(end_coarse.kinetic != coarse.initial_totals.kinetic);  // something happened

  // Half the Courant factor, to the same time: the energy error falls as dt^2 (at least twofold;
  // the variable time step makes the leapfrog only nearly symplectic).
  const auto end_fine = run_box<2>(0.15, coarse.time, 0, fine);
  REQUIRE(fine.time == coarse.time);
  const double error_fine = std::fabs(end_fine.total - fine.initial_totals.total) / fine.initial_totals.total;
  CHECK(error_fine < 0.5 * error_coarse);
}

namespace {
struct tube_run : sph::simulation<1> {};

/// 60 fluid particles between two walls of 8 particles, high pressure on the left half.
void load_tube(tube_run& s) {
  const int fluid = 60, walls = 8, total = fluid + 2 * walls;
  sph::create_particles(s, total);
  const double spacing = 1.0 / fluid;
  sph::initial_fields(s, [&](std::size_t i, sph::initial_particle<1>& p) {
    p.x = {(double(i) - walls + 0.5) * spacing};
    p.id = i;
    p.m = spacing;
    p.h = s.physics.eta * spacing;
    p.u = p.x[0] < 0.5 ? 2.5 : 0.5;
    p.kind = (int(i) < walls || int(i) >= walls + fluid) ? sph::particle_kind::wall : sph::particle_kind::fluid;
  });
}
}  // namespace

TEST_CASE("wall particles stay put; fluid plus wall impulse conserves momentum", "[sph][integration]") {
  using f = sph::fields<1>;
  tube_run s;
  s.physics.eos.ideal.gamma = 1.4;
  s.run.end_time = 0.15;  // the waves reach both walls
  s.run.progress_every = 0;
  s.run.diagnostics_every = 0;
  auto m = sph::make_control_model<tube_run>();
  m.action("initial_data", "tube", load_tube);
  m.run(s);
  REQUIRE(s.time == 0.15);
  auto& p = *s.particles;
  const auto x = flecsi_lite::host_view(f::position()(p));
  const auto v = flecsi_lite::host_view(f::velocity(p));
  const auto id = flecsi_lite::host_view(f::id()(p));
  const auto kind = flecsi_lite::host_view(f::kind(p));
  const auto mass = flecsi_lite::host_view(f::mass()(p));
  const auto impulse = flecsi_lite::host_view(f::boundary_impulse(p));
  double fluid_momentum = 0, wall_impulse = 0;
  for (std::size_t i = 0; i < p.owned_size(); ++i) {
    if (kind(i) == sph::particle_kind::wall) {
      CHECK(x(i)[0] == (double(id(i)) - 8 + 0.5) / 60);  // not moved by a single bit
      CHECK(v(i)[0] == 0.0);
      wall_impulse += mass(i) * impulse(i)[0];
    } else {
      fluid_momentum += mass(i) * v(i)[0];
      CHECK(x(i)[0] > 0.0);  // no fluid particle leaked through a wall
      CHECK(x(i)[0] < 1.0);
    }
  }
  CHECK(fluid_momentum > 1e-3);  // the walls pushed the fluid: its momentum changed
  CHECK(wall_impulse < -1e-3);   // and took the opposite impulse
  CHECK(std::fabs(s.totals.momentum[0]) < 1e-15);
  CHECK(std::fabs(s.totals.total - s.initial_totals.total) < 1e-4 * s.initial_totals.total);
}
