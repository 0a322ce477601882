// Fields follow their topology: one permutation or resize reorders every field at once.
#include <catch2/catch.hpp>

#include "flecsi_lite/data.hh"
#include "flecsi_lite/execution.hh"

#include <array>

using namespace flecsi_lite;

namespace {
// A minimal topology that lets the test drive resizing and reordering.
struct bag : data::topology_base {
  explicit bag(std::size_t n) { set_sizes(n, 0); }
  void reorder(const std::vector<std::size_t>& order) { reorder_owned(order, 0); }
  void resize(std::size_t n) { set_sizes(n, 0); }
};
const field<double>::definition<bag> mass{"mass"};
const field<std::int64_t>::definition<bag> id{"id"};
const field<std::array<double, 3>>::definition<bag> position{"position"};

void fill(field<double>::accessor<wo> m, field<std::int64_t>::accessor<wo> i,
          field<std::array<double, 3>>::accessor<wo> x) {
  for (std::size_t k = 0; k < m.size(); ++k) {
    m(k) = 10.0 * k;
    i(k) = static_cast<std::int64_t>(k);
    x(k) = {double(k), 2.0 * k, 3.0 * k};
  }
}
}  // namespace

TEST_CASE("every field is reordered by the same permutation") {
  bag b(5);
  execute<fill>(mass(b), id(b), position(b));
  b.reorder({4, 2, 0, 3, 1});
  auto m = host_view(mass(b));
  auto i = host_view(id(b));
  auto x = host_view(position(b));
  const std::vector<std::int64_t> expected{4, 2, 0, 3, 1};
  REQUIRE(b.owned_size() == 5);
  for (std::size_t k = 0; k < 5; ++k) {
    CHECK(i(k) == expected[k]);
    CHECK(m(k) == 10.0 * expected[k]);
    CHECK(x(k)[2] == 3.0 * expected[k]);
  }
}

TEST_CASE("a reorder may select a subset and a resize keeps the leading values") {
  bag b(6);
  execute<fill>(mass(b), id(b), position(b));
  b.reorder({5, 1});
  CHECK(b.owned_size() == 2);
  CHECK(host_view(id(b))(0) == 5);
  b.resize(4);
  auto i = host_view(id(b));
  REQUIRE(i.extent(0) == 4);
  CHECK(i(0) == 5);
  CHECK(i(1) == 1);
  CHECK(i(3) == 0);  // new entities are value-initialized
}

TEST_CASE("a field used with two types is a clear error") {
  bag b(2);
  mass(b).storage();  // created as double
  CHECK_THROWS_WITH((b.storage<float>(mass.id(), "mass")), Catch::Contains("two different types"));
}
