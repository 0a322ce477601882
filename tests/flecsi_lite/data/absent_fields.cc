// A field passed as only_if(false) is absent: the task gets an empty accessor (size 0, data()
// null) and the field never takes memory; only_if(true) is the field itself.
#include <catch2/catch.hpp>

#include "flecsi_lite/data.hh"
#include "flecsi_lite/execution.hh"

using namespace flecsi_lite;

namespace {
struct bag : data::topology_base {
  explicit bag(std::size_t n) { set_sizes(n, 0); }
};
const field<double>::definition<bag> energy{"energy"};
const field<double>::definition<bag> optional_factor{"optional_factor"};

// Writes 2 * factor, or 1 where the factor is absent (the null-pointer path of a physics that is off).
void scale(field<double>::accessor<ro> factor, field<double>::accessor<wo> e) {
  const double* f = factor.data();
  for (std::size_t k = 0; k < e.size(); ++k) e(k) = f ? 2.0 * f[k] : 1.0;
}
void fill(field<double>::accessor<wo> factor) {
  for (std::size_t k = 0; k < factor.size(); ++k) factor(k) = double(k);
}
bool allocated(const bag& b, std::size_t id) { return id < b.storages().size() && b.storages()[id]; }
}  // namespace

TEST_CASE("an absent field reaches the task as an empty accessor and takes no memory", "[data]") {
  bag b(4);
  execute<scale>(optional_factor(b).only_if(false), energy(b));
  auto e = host_view(energy(b));
  for (std::size_t k = 0; k < 4; ++k) CHECK(e(k) == 1.0);
  CHECK_FALSE(allocated(b, optional_factor.id()));
  CHECK_FALSE(optional_factor(b).only_if(false).present());
  CHECK_THROWS_WITH(optional_factor(b).only_if(false).storage(), Catch::Contains("'optional_factor' is absent"));
  CHECK_FALSE(allocated(b, optional_factor.id()));
}

TEST_CASE("only_if(true) is the field itself, with its dependencies", "[data]") {
  bag b(4);
  execute<fill>(optional_factor(b).only_if(true));
  execute<scale>(optional_factor(b).only_if(true), energy(b));
  auto e = host_view(energy(b));
  for (std::size_t k = 0; k < 4; ++k) CHECK(e(k) == 2.0 * k);
  CHECK(allocated(b, optional_factor.id()));
}
