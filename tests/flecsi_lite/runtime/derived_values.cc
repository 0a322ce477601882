// Particle counts checked against memory (derived_values.hh: checked_particles; job_memory.hh):
// a count that cannot fit is a parameter error naming its keys and the bytes it needs.
#include <catch2/catch.hpp>

#include "flecsi_lite/runtime/derived_values.hh"
#include "flecsi_lite/runtime/job_memory.hh"
#include "flecsi_lite/runtime/parameters.hh"

#include <sys/resource.h>

#include <cmath>
#include <string>

using namespace flecsi_lite::runtime;

namespace {
std::string refusal(double particles, double memory) {
  try {
    checked_particles("sedov", particles, "particles_per_side, dimension", memory);
  } catch (const parameter_error& e) {
    return e.what();
  }
  return "";
}
}  // namespace

TEST_CASE("a particle count within memory is returned, one beyond it names its keys and bytes") {
  const double memory = 1e9;
  const double fits = std::floor(memory / least_bytes_per_particle);
  CHECK(checked_particles("sedov", fits, "particles_per_side, dimension", memory) == static_cast<std::int64_t>(fits));
  const std::string message = refusal(fits + 1, memory);
  CHECK_THAT(message, Catch::StartsWith("sedov: particles = ") &&
                        Catch::Contains("(from particles_per_side, dimension)") &&
                        Catch::Contains("bytes a particle), more than the 1e+09 bytes this job may use") &&
                        Catch::Contains("lower particles_per_side, dimension"));
  // Beyond 2^40 the count check comes first, whatever the memory.
  CHECK_THAT(refusal(std::ldexp(1.0, 41), INFINITY), Catch::Contains("must be a count in [0, 2^40]"));
  CHECK_THAT(refusal(NAN, INFINITY), Catch::Contains("must be a count"));
}

TEST_CASE("a rank's memory limit includes its address-space limit") {
  rlimit saved{};
  REQUIRE(getrlimit(RLIMIT_AS, &saved) == 0);
  const rlim_t lowered = rlim_t{3} << 40;  // 3 TiB: below any hard limit worth setting, no allocation fails
  if (saved.rlim_max != RLIM_INFINITY && saved.rlim_max < lowered) {
    WARN("the hard address-space limit is below 3 TiB: not lowered");
    return;
  }
  rlimit limit = saved;
  limit.rlim_cur = lowered;
  REQUIRE(setrlimit(RLIMIT_AS, &limit) == 0);
  const double seen = rank_memory_limit();
  REQUIRE(setrlimit(RLIMIT_AS, &saved) == 0);
  CHECK(seen <= double(lowered));
  CHECK(physical_memory() > 0);
}
