// Sedov-Taylor solution: published energy constants and similarity profiles (Sedov 1959; Kamm
// 2000; Kamm & Timmes 2007), post-shock jump, and conservation of energy and mass of the profile.
#include "specialization/analytic/sedov_taylor.hh"

#include "specialization/analytic/quadrature.hh"

#include <catch2/catch.hpp>

#include <cmath>
#include <initializer_list>
#include <stdexcept>

using namespace flecsph::analytic;

namespace {

constexpr double pi = 3.14159265358979323846;

double unit_sphere_surface(int dimension) { return dimension == 1 ? 2.0 : (dimension == 2 ? 2.0 * pi : 4.0 * pi); }

/// int_0^R q(r) S_D r^(D-1) dr of a quantity of the sampled profile at time t.
template<class Quantity>
double volume_integral(const sedov_taylor& blast, double t, Quantity&& quantity) {
  const gauss_legendre_rule rule(20);
  const double R = blast.shock_radius(t);
  const int D = blast.dimension();
  return integrate([&](double r) { return quantity(blast.at(r, t)) * unit_sphere_surface(D) * std::pow(r, D - 1); },
                   0.0, R, 24, rule);
}

}  // namespace

TEST_CASE("energy constants match published values", "[sedov]") {
  // Kamm & Timmes (2007) test problems, gamma = 1.4, rho0 = 1, t = 1: spherical E = 0.851072
  // puts the shock at R = 1, cylindrical E = 0.311357 at R = 0.75. Their planar problem,
  // E = 0.0673185 for R = 0.5, counts the energy of one half-space (x > 0) and is printed to
  // about 4 digits; our planar E is that of the whole slab, twice theirs.
  CHECK(sedov_taylor(3, 1.4, 0.851072, 1.0).shock_radius(1.0) == Approx(1.0).epsilon(1e-6));
  CHECK(sedov_taylor(3, 1.4, 1.0, 1.0).alpha() == Approx(0.851072).epsilon(1e-6));
  CHECK(sedov_taylor(2, 1.4, 0.311357, 1.0).shock_radius(1.0) == Approx(0.75).epsilon(2e-5));
  CHECK(sedov_taylor(1, 1.4, 2.0 * 0.0673185, 1.0).shock_radius(1.0) == Approx(0.5).epsilon(2e-4));
  // xi0 = alpha^(-1/(D+2)): 1.033 for gamma = 1.4 and 1.152 for gamma = 5/3 in 3D (Sedov 1959;
  // e.g. Springel 2010, Hopkins 2015).
  CHECK(sedov_taylor(3, 1.4, 1.0, 1.0).xi0() == Approx(1.033).margin(5e-4));
  CHECK(sedov_taylor(3, 5.0 / 3.0, 1.0, 1.0).xi0() == Approx(1.152).margin(5e-4));
  // Independent high-precision quadrature (mpmath, 40 digits, tanh-sinh rule directly in V
  // on Kamm & Timmes eqs. 55-56, whose endpoint singularity that rule absorbs).
  struct reference {
    int dimension;
    double gamma, alpha;
  };
  for (const reference& value : {reference{1, 1.4, 1.0774855847137},
                                 {1, 5.0 / 3.0, 0.60293523791993},
                                 {1, 3.0, 0.14192343604108},
                                 {2, 1.4, 0.98407401688003},
                                 {2, 5.0 / 3.0, 0.564283436899},
                                 {2, 3.0, 0.14440322872026},
                                 {3, 1.4, 0.85107185475823},
                                 {3, 5.0 / 3.0, 0.49359014958257},
                                 {3, 3.0, 0.13252408364445}}) {
    INFO("D = " << value.dimension << ", gamma = " << value.gamma);
    CHECK(sedov_taylor(value.dimension, value.gamma, 1.0, 1.0).alpha() == Approx(value.alpha).epsilon(1e-9));
  }
}

TEST_CASE("similarity profiles match Sedov's and Kamm's tables", "[sedov]") {
  // Kamm (2000), LA-UR-00-6055, Tables 1-3 (gamma = 1.4): lambda, f, g, h to 4 decimals.
  struct row {
    double lambda, f, g, h;
  };
  const row spherical[] = {{0.9913, 0.9814, 0.8388, 0.9116},
                           {0.9342, 0.8745, 0.3248, 0.5929},
                           {0.7493, 0.6497, 0.0379, 0.3857},
                           {0.4560, 0.3909, 0.0009, 0.3656},
                           {0.1040, 0.0891, 0.0000, 0.3655}};
  const row cylindrical[] = {{0.9802, 0.9645, 0.7651, 0.8658},
                             {0.8725, 0.7999, 0.2427, 0.5266},
                             {0.6390, 0.5521, 0.0362, 0.3867},
                             {0.3000, 0.2572, 0.0008, 0.3730}};
  const row planar[] = {{0.9797, 0.9699, 0.8620, 0.9159},
                        {0.8050, 0.7390, 0.3020, 0.5458},
                        {0.5396, 0.4682, 0.0826, 0.4112},
                        {0.1040, 0.0891, 0.0013, 0.3900}};
  auto check_rows = [](int dimension, const auto& rows) {
    const sedov_taylor blast(dimension, 1.4, 1.0, 1.0);
    for (const row& expected : rows) {
      INFO("D = " << dimension << ", lambda = " << expected.lambda);
      const sedov_similarity values = blast.similarity(expected.lambda);
      CHECK(values.f == Approx(expected.f).margin(1e-4));
      CHECK(values.g == Approx(expected.g).margin(1e-4));
      CHECK(values.h == Approx(expected.h).margin(1e-4));
    }
  };
  check_rows(3, spherical);
  check_rows(2, cylindrical);
  check_rows(1, planar);
}

TEST_CASE("post-shock state is the strong-shock jump", "[sedov]") {
  // Kamm & Timmes (2007) eqs. 13-18 for their spherical problem: rho = 6, v = 1/3, P = 2/15,
  // u = 1/18 just behind the shock at R = 1, t = 1.
  const sedov_taylor blast(3, 1.4, 0.851072, 1.0);
  const double R = blast.shock_radius(1.0);
  const sedov_state behind = blast.at(R * (1.0 - 1e-12), 1.0);
  CHECK(behind.rho == Approx(6.0).epsilon(1e-6));
  CHECK(behind.v == Approx(1.0 / 3.0).epsilon(1e-6));
  CHECK(behind.P == Approx(2.0 / 15.0).epsilon(1e-6));
  CHECK(blast.specific_internal_energy(behind) == Approx(1.0 / 18.0).epsilon(1e-6));
  for (double gamma : {1.2, 1.4, 5.0 / 3.0, 2.0}) {
    for (int dimension : {1, 2, 3}) {
      const sedov_taylor other(dimension, gamma, 2.5, 0.7);
      const double t = 0.3;
      const double radius = other.shock_radius(t);
      CHECK(other.at(radius, t).rho == Approx(0.7 * (gamma + 1.0) / (gamma - 1.0)));
      CHECK(other.at(radius, t).rho == Approx(other.post_shock(t).rho));
      CHECK(other.at(radius * (1.0 - 1e-9), t).P == Approx(other.post_shock(t).P).epsilon(1e-6));
      const sedov_state outside = other.at(radius * 1.001, t);
      CHECK(outside.rho == 0.7);
      CHECK(outside.v == 0.0);
      CHECK(outside.P == 0.0);
      // Centre: empty, at rest, at finite pressure.
      const sedov_state centre = other.at(0.0, t);
      CHECK(centre.rho == 0.0);
      CHECK(centre.v == 0.0);
      CHECK(centre.P > 0.0);
      CHECK(std::isinf(other.specific_internal_energy(centre)));
    }
  }
  // R grows as t^(2/(D+2)).
  const sedov_taylor cylinder(2, 1.4, 1.0, 1.0);
  CHECK(cylinder.shock_radius(4.0) == Approx(cylinder.shock_radius(1.0) * 2.0));
  CHECK(cylinder.shock_velocity(1.0) == Approx(0.5 * cylinder.shock_radius(1.0)));
}

TEST_CASE("integrated profile gives back the blast energy and the swept-up mass", "[sedov]") {
  for (int dimension : {1, 2, 3}) {
    for (double gamma : {1.4, 5.0 / 3.0, 2.0, 3.0}) {
      const double energy = 1.7, rho0 = 0.9, t = 0.05;
      const sedov_taylor blast(dimension, gamma, energy, rho0);
      INFO("D = " << dimension << ", gamma = " << gamma);
      const double total =
        volume_integral(blast, t, [&](const sedov_state& q) { return 0.5 * q.rho * q.v * q.v + q.P / (gamma - 1.0); });
      CHECK(total == Approx(energy).epsilon(1e-3));
      CHECK(total == Approx(energy).epsilon(1e-6));  // in fact to quadrature accuracy
      const double mass = volume_integral(blast, t, [](const sedov_state& q) { return q.rho; });
      const double R = blast.shock_radius(t);
      CHECK(mass == Approx(rho0 * unit_sphere_surface(dimension) * std::pow(R, dimension) / dimension).epsilon(1e-6));
    }
  }
}

TEST_CASE("gamma = 2 (the omega3 removable singularity) is continuous with its neighbours", "[sedov]") {
  for (int dimension : {1, 2, 3}) {
    const sedov_taylor at_two(dimension, 2.0, 1.0, 1.0);
    for (double delta : {-1e-6, 1e-6}) {
      const sedov_taylor near(dimension, 2.0 + delta, 1.0, 1.0);
      INFO("D = " << dimension << ", delta = " << delta);
      CHECK(near.alpha() == Approx(at_two.alpha()).epsilon(5e-6));
      for (double lambda : {0.0, 0.3, 0.7, 0.95}) {
        CHECK(near.similarity(lambda).g == Approx(at_two.similarity(lambda).g).epsilon(5e-6));
        CHECK(near.similarity(lambda).h == Approx(at_two.similarity(lambda).h).epsilon(5e-6));
        CHECK(near.similarity(lambda).f == Approx(at_two.similarity(lambda).f).epsilon(5e-6));
      }
    }
  }
}

TEST_CASE("invalid Sedov parameters are rejected", "[sedov]") {
  CHECK_THROWS_AS(sedov_taylor(0, 1.4, 1.0, 1.0), std::invalid_argument);
  CHECK_THROWS_AS(sedov_taylor(4, 1.4, 1.0, 1.0), std::invalid_argument);
  CHECK_THROWS_AS(sedov_taylor(3, 1.0, 1.0, 1.0), std::invalid_argument);
  CHECK_THROWS_AS(sedov_taylor(3, 7.0, 1.0, 1.0), std::invalid_argument);
  CHECK_THROWS_AS(sedov_taylor(3, 1.4, 0.0, 1.0), std::invalid_argument);
  CHECK_THROWS_AS(sedov_taylor(3, 1.4, 1.0, -1.0), std::invalid_argument);
  const sedov_taylor blast(3, 1.4, 1.0, 1.0);
  CHECK_THROWS_AS(blast.shock_radius(0.0), std::invalid_argument);
  CHECK_THROWS_AS(blast.at(-0.1, 1.0), std::invalid_argument);
  CHECK_THROWS_AS(blast.similarity(1.1), std::invalid_argument);
  CHECK_NOTHROW(sedov_taylor(2, 9.0, 1.0, 1.0));  // no upper limit on gamma in 2D
}
