// I/O errors keep their kind across ranks: throw_io_error rebuilds the subclass of every kind.
#include <catch2/catch.hpp>

#include "flecsi_lite/io/io_error.hh"

using namespace flecsi_lite::io;

namespace {
template<class Expected>
void check_kind(failure kind) {
  try {
    throw_io_error(kind, "message");
  } catch (const Expected& e) {
    CHECK(e.kind() == kind);
    CHECK(std::string(e.what()) == "message");
    return;
  } catch (...) {}
  FAIL("wrong exception type for kind " << static_cast<int>(kind));
}
}  // namespace

TEST_CASE("every failure kind is thrown as its own subclass") {
  check_kind<file_error>(failure::file);
  check_kind<missing_step_error>(failure::step);
  check_kind<missing_dataset_error>(failure::dataset);
  check_kind<missing_attribute_error>(failure::attribute);
  check_kind<layout_error>(failure::layout);
  check_kind<element_type_error>(failure::type);
  check_kind<slice_error>(failure::slice);
  check_kind<usage_error>(failure::usage);
  check_kind<io_error>(failure::system);
  CHECK_THROWS_AS(throw_io_error(failure::file, "x"), std::runtime_error);
}
