// Threads per rank: the share of a node's cores (cores, ranks on the node, user's choice) and the
// user's choice read from the environment and from both spellings of Kokkos' thread option.
#include "flecsi_lite/runtime/thread_share.hh"

#include <catch2/catch.hpp>

#include <Kokkos_Core.hpp>

#include <cstdlib>

using namespace flecsi_lite::runtime;

TEST_CASE("each rank gets its share of the node's cores, at least one thread") {
  STATIC_REQUIRE(threads_per_rank(2, 2) == 1);
  STATIC_REQUIRE(threads_per_rank(2, 1) == 2);
  STATIC_REQUIRE(threads_per_rank(16, 4) == 4);
  STATIC_REQUIRE(threads_per_rank(16, 3) == 5);  // rounded down: never more threads than cores
  STATIC_REQUIRE(threads_per_rank(2, 4) == 1);   // more ranks than cores
  STATIC_REQUIRE(threads_per_rank(1, 1) == 1);
}

TEST_CASE("the user's choice wins over the share") {
  STATIC_REQUIRE(threads_per_rank(2, 2, 3) == 3);
  STATIC_REQUIRE(threads_per_rank(16, 1, 1) == 1);
}

TEST_CASE("the choice comes from the command line first, then OMP_NUM_THREADS or KOKKOS_NUM_THREADS") {
  unsetenv("OMP_NUM_THREADS");
  unsetenv("KOKKOS_NUM_THREADS");
  const char* none[] = {"program", "--set", "x=1"};
  CHECK(user_thread_choice(3, none).threads == 0);

  const char* new_spelling[] = {"program", "--kokkos-num-threads=3"};
  CHECK(user_thread_choice(2, new_spelling).threads == 3);
  CHECK(user_thread_choice(2, new_spelling).source == "--kokkos-num-threads");
  const char* old_spelling[] = {"program", "--kokkos-threads", "5"};
  CHECK(user_thread_choice(3, old_spelling).threads == 5);
  const char* bad[] = {"program", "--kokkos-num-threads=two"};
  CHECK(user_thread_choice(2, bad).error.find("'two'") != std::string::npos);

  setenv("KOKKOS_NUM_THREADS", "4", 1);
  CHECK(user_thread_choice(3, none).threads == 4);
  setenv("OMP_NUM_THREADS", "2,1", 1);
  CHECK(user_thread_choice(3, none).threads == 2);
  CHECK(user_thread_choice(3, none).source == "OMP_NUM_THREADS");
  CHECK(user_thread_choice(2, new_spelling).threads == 3);  // the command line wins
  unsetenv("KOKKOS_NUM_THREADS");
}

TEST_CASE("the option is spelled as the Kokkos this program is built with accepts") {
  const std::string option = kokkos_thread_option();
  CHECK(option == (KOKKOS_VERSION >= 40000 ? "--kokkos-num-threads" : "--kokkos-threads"));
}
