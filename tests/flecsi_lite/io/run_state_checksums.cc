// The run state's checksums (run_state_checksums.hh): FNV-1a over a value's kind and exact bytes,
// against an independent implementation, and changed_values naming exactly what differs.
#include <catch2/catch.hpp>

#include "flecsi_lite/io/run_state_checksums.hh"

#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

using namespace flecsi_lite::io;

TEST_CASE("FNV-1a of a value's kind byte and little-endian bytes") {
  // From Python (whose loop gives 0xaf63dc4c8601ec8c for "a", the published FNV-1a 64 vector):
  //   h = 0xcbf29ce484222325; for b in bytes([kind]) + data: h = ((h ^ b) * 0x100000001b3) % 2**64
  // with data struct.pack('<q', 0), struct.pack('<d', 1.0), b'sod' for kinds 0, 1, 2.
  CHECK(fnv1a(std::int64_t{0}) == 0xe604823a249029bfull);
  CHECK(fnv1a(1.0) == 0x50b0a3dc8e5526f1ull);
  CHECK(fnv1a(std::string("sod")) == 0x0ae4d790006454c9ull);
}

TEST_CASE("every bit of a value and its kind count") {
  const double dt = 1e-3;
  CHECK(fnv1a(dt) != fnv1a(std::nextafter(dt, 1.0)));
  CHECK(fnv1a(0.0) != fnv1a(-0.0));
  CHECK(fnv1a(std::int64_t{1}) != fnv1a(1.0));
  CHECK(fnv1a(std::numeric_limits<double>::quiet_NaN()) == fnv1a(std::numeric_limits<double>::quiet_NaN()));
}

TEST_CASE("changed_values names the changed, the unlisted and the missing values") {
  const checked_values written{{"dt", 1e-3}, {"step", std::int64_t{12}}, {"state:program", std::string("sod")}};
  const std::string checksums = checksums_text(written);
  CHECK(changed_values(checksums, written).empty());

  checked_values changed = written;
  changed["step"] = std::int64_t{6};
  changed["state:extra"] = 1.0;
  changed.erase("state:program");
  CHECK(changed_values(checksums, changed) == std::vector<std::string>{"state:extra", "state:program", "step"});
  // A line that is no "<name> <hex>" counts as changed, named as written.
  CHECK(changed_values(checksums + "garbage\n", written) == std::vector<std::string>{"garbage"});
}
