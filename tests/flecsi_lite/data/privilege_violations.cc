// Code that breaks a task's privileges must not compile: each PRIVILEGE_CASE (1, 2, ...) is one
// violation, built by the tests data.privileges.compile_fail.N and expected to fail with the
// named diagnostic; case 0 (data.privileges.compile_within) obeys its privileges and must build.
#include "flecsi_lite/data.hh"
#include "flecsi_lite/execution.hh"

#include <vector>

using namespace flecsi_lite;

namespace {
[[maybe_unused]] void read_only(field<double>::accessor<ro> f, double& out) {
#if PRIVILEGE_CASE == 1
  f(0) = 1.0;  // writes through a read-only accessor
#endif
  out = f(0);
}
[[maybe_unused]] void read_only_with_ghosts(field<double>::accessor<ro, ro> f) {
#if PRIVILEGE_CASE == 2
  f.data()[0] = 1.0;  // writes through the raw array of a read-only accessor
#endif
  (void)f;
}
[[maybe_unused]] void owned_writer(field<double>::accessor<rw, ro> f) {
  f.owned(0) = f(f.owned_size());  // owned values are writable, ghosts readable
#if PRIVILEGE_CASE == 3
  f.ghost(0) = 1.0;  // ghost privilege ro
#endif
#if PRIVILEGE_CASE == 4
  f(0) = 1.0;  // f(i) spans the read-only ghosts too
#endif
}
[[maybe_unused]] void ghost_writer(field<double>::accessor<na, wo> f) {
  f.ghost(0) = 1.0;
#if PRIVILEGE_CASE == 5
  f.owned(0) = 1.0;  // owned privilege na
#endif
}
[[maybe_unused]] void appends(std::vector<double>& values) { values.push_back(1.0); }
[[maybe_unused]] double first(const std::vector<double>& values) { return values.front(); }
}  // namespace

void launch_with_arguments(std::vector<double>& values) {
  execute<first>(values);  // a const reference: the task gets a copy made at launch
#if PRIVILEGE_CASE == 6
  execute<appends>(values);  // a non-const reference to a type that is not a shared_argument
#endif
}
