// Privileges are enforced per region: read-only regions give const access (checked on the types:
// writing through them does not compile, see privilege_violations.cc), na regions are out of
// reach (a ghost-only accessor touching an owned entity fails naming the field), wo / rw write.
#include <catch2/catch.hpp>

#include "flecsi_lite/data.hh"
#include "flecsi_lite/execution.hh"

#include <string>
#include <type_traits>

using namespace flecsi_lite;

namespace {
template<privilege O, privilege G>
using acc = field<double>::accessor<O, G>;
template<class A>
using at = decltype(std::declval<const A&>()(0));
template<class A>
using owned_at = decltype(std::declval<const A&>().owned(0));
template<class A>
using ghost_at = decltype(std::declval<const A&>().ghost(0));
template<class A>
constexpr bool writable = std::is_assignable_v<at<A>, double>;

// Owned only.
static_assert(std::is_same_v<at<acc<ro, na>>, const double&> && !writable<acc<ro, na>>);
static_assert(std::is_same_v<at<acc<wo, na>>, double&> && writable<acc<wo, na>>);
static_assert(std::is_same_v<at<acc<rw, na>>, double&> && writable<acc<rw, na>>);
static_assert(std::is_same_v<decltype(std::declval<acc<ro, na>>().data()), const double*>);
static_assert(std::is_same_v<owned_at<acc<ro, na>>, const double&>);
static_assert(std::is_same_v<owned_at<acc<rw, na>>, double&>);
// Both regions: f(i) writes only when both are writable; owned(i) / ghost(j) follow their region.
static_assert(!writable<acc<ro, ro>>);
static_assert(std::is_same_v<decltype(std::declval<acc<ro, ro>>().data()), const double*>);
static_assert(writable<acc<rw, rw>> && writable<acc<wo, rw>>);
static_assert(!writable<acc<rw, ro>> && !writable<acc<ro, rw>>);
static_assert(std::is_assignable_v<owned_at<acc<rw, ro>>, double> &&
              !std::is_assignable_v<ghost_at<acc<rw, ro>>, double>);
static_assert(!std::is_assignable_v<owned_at<acc<ro, wo>>, double> &&
              std::is_assignable_v<ghost_at<acc<ro, wo>>, double>);
// Ghosts only: f(i) is the ghost region's (owned entities fail at run time).
static_assert(writable<acc<na, wo>> && !writable<acc<na, ro>>);
static_assert(std::is_same_v<ghost_at<acc<na, wo>>, double&> && std::is_same_v<ghost_at<acc<na, ro>>, const double&>);
// A task parameter's element types are the executor's view of its privileges too.
static_assert(acc<na, wo>::owned_privilege == na && acc<na, wo>::ghost_privilege == wo);

// A topology with owned and ghost entities and no peers: the ghosts are written by tasks.
struct bag : data::topology_base {
  bag(std::size_t owned, std::size_t ghosts) { set_sizes(owned, ghosts); }
};
const field<double>::definition<bag> pressure{"pressure"};

void fill(field<double>::accessor<wo, wo> f) {
  for (std::size_t i = 0; i < f.size(); ++i) f(i) = double(i);
}
void negate_ghosts(field<double>::accessor<na, wo> f) {
  for (std::size_t i = f.owned_size(); i < f.size(); ++i) f(i) = -f(i);
}
void touch_owned(field<double>::accessor<na, wo> f) { f(0) = 42.0; }
double read_owned(field<double>::accessor<na, ro> f) { return f(f.owned_size() - 1); }
void owned_from_ghost(field<double>::accessor<rw, ro> f) {
  for (std::size_t i = 0; i < f.owned_size(); ++i) f.owned(i) += f.ghost(0);
}
double at_index(field<double>::accessor<ro, ro> f, std::size_t i) { return f(i); }
double owned_value(field<double>::accessor<ro> f, std::size_t i) { return f(i); }
}  // namespace

TEST_CASE("a ghost-only accessor writes ghosts and nothing else") {
  bag b(4, 2);
  execute<fill>(pressure(b));
  execute<negate_ghosts>(pressure(b));
  CHECK(execute<at_index>(pressure(b), 3).get() == 3.0);   // owned untouched
  CHECK(execute<at_index>(pressure(b), 4).get() == -4.0);  // ghosts negated
  CHECK(execute<at_index>(pressure(b), 5).get() == -5.0);
}

TEST_CASE("an owned entity through a ghost-only accessor fails, naming the field") {
  bag b(4, 2);
  execute<fill>(pressure(b));
  CHECK_THROWS_WITH(execute<touch_owned>(pressure(b)).get(), Catch::Contains("field 'pressure'") &&
                                                               Catch::Contains("accessor<na, wo>") &&
                                                               Catch::Contains("owned entity 0"));
  CHECK(execute<owned_value>(pressure(b), 0).get() == 0.0);  // the write did not happen
  execute<fill>(pressure(b));                                // the ghosts are defined again
  CHECK_THROWS_WITH(execute<read_owned>(pressure(b)).get(), Catch::Contains("field 'pressure'") &&
                                                              Catch::Contains("accessor<na, ro>") &&
                                                              Catch::Contains("owned entity 3"));
  execution::executor::instance().forgive_failures();
}

TEST_CASE("owned(i) writes the owned region of an accessor whose ghosts are read-only") {
  bag b(3, 1);
  execute<fill>(pressure(b));
  execute<owned_from_ghost>(pressure(b));
  CHECK(execute<at_index>(pressure(b), 0).get() == 3.0);
  CHECK(execute<at_index>(pressure(b), 2).get() == 5.0);
  CHECK(execute<at_index>(pressure(b), 3).get() == 3.0);
}
