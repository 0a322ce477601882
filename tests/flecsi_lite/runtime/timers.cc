// Timers: readable row names for C++ task names, and the covered time (the union of the timed
// intervals) that the "unaccounted" row subtracts from the wall time, counting nested timers once.
#include <catch2/catch.hpp>

#include "flecsi_lite/runtime/timers.hh"

#include <chrono>
#include <thread>

namespace timers = flecsi_lite::timers;

TEST_CASE("timer names lose template arguments, detail namespaces and all but one namespace") {
  CHECK(timers::readable_name("flecsph::sph::compute_density<2>") == "sph::compute_density");
  CHECK(timers::readable_name("flecsph::sph::detail::set_initial_fields<1>") == "sph::set_initial_fields");
  CHECK(timers::readable_name("flecsi_lite::topology::ntree::detail::build_tree<3>") == "ntree::build_tree");
  CHECK(timers::readable_name("a::b::f<c::d<1, 2>, 3>") == "b::f");
  CHECK(timers::readable_name("{anonymous}::work") == "work");
  CHECK(timers::readable_name("(anonymous namespace)::work<1>") == "work");
  CHECK(timers::readable_name("solo") == "solo");
  // Phrases are names people chose: kept.
  CHECK(timers::readable_name("ntree::distribute local tree") == "ntree::distribute local tree");
  CHECK(timers::readable_name("tutorial work") == "tutorial work");
}

TEST_CASE("the covered time counts a nested timer once, sequential ones each") {
  using namespace std::chrono_literals;
  timers::clear();
  CHECK(timers::covered_seconds() == 0);
  const auto before = std::chrono::steady_clock::now();
  {
    timers::scoped outer("outer");
    {
      timers::scoped inner("inner");
      std::this_thread::sleep_for(20ms);
    }
    std::this_thread::sleep_for(20ms);
  }
  const double span = std::chrono::duration<double>(std::chrono::steady_clock::now() - before).count();
  const double nested = timers::covered_seconds();
  // The inner interval lies inside the outer one: covered is the outer call alone (>= 40 ms, at
  // most the span measured around it), not outer + inner (>= span + 20 ms).
  CHECK(nested >= 0.040);
  CHECK(nested <= span + 1e-4);
  CHECK(nested <= timers::wall_seconds());
  {
    timers::scoped after("after");
    std::this_thread::sleep_for(20ms);
  }
  CHECK(timers::covered_seconds() >= nested + 0.020);
  CHECK(timers::covered_seconds() <= timers::wall_seconds());
  timers::clear();
  CHECK(timers::covered_seconds() == 0);
  CHECK(timers::wall_seconds() < nested);
}
