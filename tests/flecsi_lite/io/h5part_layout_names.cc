// H5Part step group names: Step#<k> written and parsed back; other names are not steps.
#include <catch2/catch.hpp>

#include "flecsi_lite/io/detail/h5part_layout.hh"

using namespace flecsi_lite::io::h5part;

TEST_CASE("step group names round-trip") {
  for (std::int64_t k : {0ll, 1ll, 9ll, 10ll, 123456789012ll}) {
    CHECK(step_group_name(k) == "Step#" + std::to_string(k));
    CHECK(parse_step_group_name(step_group_name(k)) == k);
  }
}

TEST_CASE("names that H5Part never writes are not steps") {
  for (const char* name : {"Step#", "Step#-1", "Step#+1", "Step#01", "Step#1a", "Step 1", "step#1", "Step#1 ",
                           "Step#99999999999999999999", "x", ""})
    CHECK_FALSE(parse_step_group_name(name).has_value());
}
