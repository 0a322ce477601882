// Ghost copies happen exactly when a launch reads stale ghost values, and deliver the owners'
// values, sending only those that changed since the last copy; a diffusion run on the narray
// matches the serial computation bit for bit.
#include <catch2/catch.hpp>

#include "flecsi_lite/data.hh"
#include "flecsi_lite/execution.hh"
#include "flecsi_lite/runtime/context.hh"
#include "flecsi_lite/topology/narray.hh"
#include "index_values.hh"

#include <cmath>

using namespace flecsi_lite;
using testing::all_ranks;
using testing::fill_scaled_index;
using testing::ghosts_hold;
using topology::narray;

namespace {
const field<double>::definition<narray> u{"u"};
const field<double>::definition<narray> next{"next"};

void write_ghosts(field<double>::accessor<na, wo> f) {
  for (std::size_t i = f.owned_size(); i < f.size(); ++i) f(i) = -1;
}
double owned_sum(field<double>::accessor<ro> f) {
  double s = 0;
  for (std::size_t i = 0; i < f.size(); ++i) s += f(i);
  return s;
}
void smooth(const narray& n, field<double>::accessor<ro, ro> from, field<double>::accessor<wo> to) {
  forall(to.size(), [&](std::size_t i) {
    const double left = from(n.neighbor(i, -1)), right = from(n.neighbor(i, 1));
    to(i) = from(i) + 0.25 * (left - 2 * from(i) + right);
  });
}
void copy_back(field<double>::accessor<ro> from, field<double>::accessor<wo> to) {
  for (std::size_t i = 0; i < to.size(); ++i) to(i) = from(i);
}

std::uint64_t copies() { return execution::executor::instance().ghost_copies_started(); }
}  // namespace

TEST_CASE("ghost copies happen when and only when ghost values are stale") {
  narray n(40, 2, true);
  const auto start = copies();
  execute<fill_scaled_index>(n, u(n), 1.0);
  CHECK(copies() == start);  // writing owned values copies nothing
  execute<owned_sum>(u(n));
  CHECK(copies() == start);  // reading owned values copies nothing
  CHECK(all_ranks(execute<ghosts_hold>(n, u(n), 1.0).get()));
  CHECK(copies() == start + 1);  // first ghost read: one copy
  execute<ghosts_hold>(n, u(n), 1.0);
  execute<ghosts_hold>(n, u(n), 1.0);
  CHECK(copies() == start + 1);              // still valid: no copy
  execute<fill_scaled_index>(n, u(n), 3.0);  // owned values change: ghosts stale
  CHECK(all_ranks(execute<ghosts_hold>(n, u(n), 3.0).get()));
  CHECK(copies() == start + 2);
  execute<write_ghosts>(u(n));  // a task defines the ghost values itself
  execute<ghosts_hold>(n, u(n), 3.0);
  CHECK(copies() == start + 2);
  wait_all();
}

TEST_CASE("ghost values come from the owning ranks, periodic and not") {
  for (bool periodic : {true, false}) {
    narray n(30, 3, periodic);
    execute<fill_scaled_index>(n, u(n), 0.5);
    CHECK(all_ranks(execute<ghosts_hold>(n, u(n), 0.5).get()));
    const std::size_t expected_ghosts =
      (periodic || runtime::rank() > 0 ? 3 : 0) + (periodic || runtime::rank() + 1 < runtime::size() ? 3 : 0);
    CHECK(n.ghost_size() == expected_ghosts);
  }
}

TEST_CASE("diffusion on any rank count equals the serial computation bitwise") {
  const std::size_t global = 97;  // not divisible by the rank counts
  narray n(global, 1, true);
  execute<fill_scaled_index>(n, u(n), 1.0);
  for (int step = 0; step < 50; ++step) {
    execute<smooth>(n, u(n), next(n));
    execute<copy_back>(next(n), u(n));
  }
  std::vector<double> serial(global), serial_next(global);
  for (std::size_t i = 0; i < global; ++i) serial[i] = double(i);
  for (int step = 0; step < 50; ++step) {
    for (std::size_t i = 0; i < global; ++i) {
      const double left = serial[(i + global - 1) % global], right = serial[(i + 1) % global];
      serial_next[i] = serial[i] + 0.25 * (left - 2 * serial[i] + right);
    }
    serial = serial_next;
  }
  auto values = host_view(u(n));
  bool identical = true;
  for (std::size_t i = 0; i < n.owned_size(); ++i) identical &= values(i) == serial[n.global_index(i)];
  CHECK(all_ranks(identical));
}

TEST_CASE("a block smaller than the halo is a clear error") {
  if (runtime::size() < 2) return;
  CHECK_THROWS_WITH(narray(3, 2, true), Catch::Contains("smaller than the halo"));
}

TEST_CASE("ghost traffic counts the messages and bytes to other ranks, none to the rank itself") {
  auto& ex = execution::executor::instance();
  for (bool periodic : {false, true}) {
    if (periodic && runtime::size() > 1) continue;  // one rank: its periodic images are no message
    narray n(40, 2, periodic);
    execute<fill_scaled_index>(n, u(n), 1.0);
    wait_all();
    const auto before = ex.traffic();
    CHECK(all_ranks(execute<ghosts_hold>(n, u(n), 1.0).get()));
    const auto after = ex.traffic();
    const std::uint64_t neighbours =
      runtime::size() == 1 ? 0 : (runtime::rank() > 0) + (runtime::rank() + 1 < runtime::size());
    CHECK(after.messages_sent - before.messages_sent == neighbours);
    CHECK(after.messages_received - before.messages_received == neighbours);
    // The first copy sends every value, after a mask of one bit per entity.
    const std::uint64_t mask = (n.halo() + 7) / 8;
    CHECK(after.bytes_sent - before.bytes_sent == neighbours * (mask + n.halo() * sizeof(double)));
    CHECK(after.bytes_received - before.bytes_received ==
          (neighbours ? neighbours * mask + n.ghost_size() * sizeof(double) : 0));
  }
}

namespace {
// Every seventh entity (global index) gets `shift` added: a few of the shared values change.
void shift_every_seventh(const narray& n, field<double>::accessor<rw> f, double shift) {
  for (std::size_t i = 0; i < f.size(); ++i)
    if (n.global_index(i) % 7 == 0) f(i) += shift;
}
bool ghosts_hold_shifted(const narray& n, field<double>::accessor<ro, ro> f, double shift) {
  for (std::size_t i = f.owned_size(); i < f.size(); ++i) {
    const std::size_t g = n.global_index(i);
    if (f(i) != static_cast<double>(g) + (g % 7 == 0 ? shift : 0.0)) return false;
  }
  return true;
}
}  // namespace

TEST_CASE("a ghost copy sends only the values that changed since the field's last copy to that peer") {
  if (runtime::size() < 2) return;  // one rank, not periodic: no copies
  auto& ex = execution::executor::instance();
  narray n(60, 3, false);
  const int rank = runtime::rank(), size = runtime::size();
  const std::size_t owned = n.owned_size(), halo = n.halo(), mask = (halo + 7) / 8;
  // The owned entities sent to the left and right neighbours, and how many of them are shifted.
  std::uint64_t neighbours = 0, shifted = 0;
  const auto count_shifted = [&](std::size_t first) {
    ++neighbours;
    for (std::size_t i = first; i < first + halo; ++i) shifted += n.global_index(i) % 7 == 0;
  };
  if (rank > 0) count_shifted(0);
  if (rank + 1 < size) count_shifted(owned - halo);
  const auto bytes_of = [&](auto&& launches) {
    const auto before = ex.traffic();
    launches();
    wait_all();
    return ex.traffic().bytes_sent - before.bytes_sent;
  };
  execute<fill_scaled_index>(n, u(n), 1.0);
  CHECK(bytes_of([&] { CHECK(all_ranks(execute<ghosts_hold>(n, u(n), 1.0).get())); }) ==
        neighbours * (mask + halo * sizeof(double)));
  // Owned values rewritten with the same bits: the copy sends the masks alone.
  CHECK(bytes_of([&] {
          execute<fill_scaled_index>(n, u(n), 1.0);
          CHECK(all_ranks(execute<ghosts_hold>(n, u(n), 1.0).get()));
        }) == neighbours * mask);
  // A few values changed: those alone.
  CHECK(bytes_of([&] {
          execute<shift_every_seventh>(n, u(n), 0.5);
          CHECK(all_ranks(execute<ghosts_hold_shifted>(n, u(n), 0.5).get()));
        }) == neighbours * mask + shifted * sizeof(double));
  // A task wrote the ghosts: the peers' ghosts no longer hold what was sent, so the next copy
  // sends every value, even those whose owned bits are the ones sent last time.
  execute<write_ghosts>(u(n));
  CHECK(bytes_of([&] {
          execute<shift_every_seventh>(n, u(n), 0.0);
          CHECK(all_ranks(execute<ghosts_hold_shifted>(n, u(n), 0.5).get()));
        }) == neighbours * (mask + halo * sizeof(double)));
  // The same after ghosts written outside tasks (host_view).
  {
    auto values = host_view(u(n));
    for (std::size_t i = owned; i < values.extent(0); ++i) values(i) = -2;
  }
  CHECK(bytes_of([&] {
          execute<shift_every_seventh>(n, u(n), 0.0);
          CHECK(all_ranks(execute<ghosts_hold_shifted>(n, u(n), 0.5).get()));
        }) == neighbours * (mask + halo * sizeof(double)));
}
