// Run-time kernel choice: names round-trip, unknown names fail clearly, and the dispatched kernel
// is the same function, also inside a Kokkos parallel reduction.
#include "specialization/physics/kernels.hh"

#include <catch2/catch.hpp>

#include <Kokkos_Core.hpp>

#include <stdexcept>
#include <string>

using namespace flecsph::physics;

TEST_CASE("kernel names round-trip", "[kernels]") {
  CHECK(kernel_from_name("cubic_spline") == kernel_type::cubic_spline);
  CHECK(kernel_from_name("wendland_c2") == kernel_type::wendland_c2);
  CHECK(kernel_from_name("wendland_c4") == kernel_type::wendland_c4);
  CHECK(kernel_from_name("wendland_c6") == kernel_type::wendland_c6);
  for (kernel_type type : all_kernel_types) CHECK(kernel_from_name(kernel_name(type)) == type);
}

TEST_CASE("unknown kernel name is a clear error", "[kernels]") {
  try {
    kernel_from_name("cubic_splin");
    FAIL("no exception");
  } catch (const std::invalid_argument& error) {
    const std::string message = error.what();
    CHECK(message.find("unknown kernel 'cubic_splin'") != std::string::npos);
    CHECK(message.find("did you mean 'cubic_spline'") != std::string::npos);
    CHECK(message.find("wendland_c6") != std::string::npos);  // lists the valid names
  }
  CHECK_THROWS_AS(kernel_from_name(""), std::invalid_argument);
  CHECK_THROWS_AS(kernel_from_name("gaussian"), std::invalid_argument);
}

TEST_CASE("dispatch gives the kernel of the requested type", "[kernels]") {
  const double r = 0.83, h = 0.61;
  auto value_of = [&](kernel_type type) {
    return dispatch_kernel<3>(type, [&](auto kernel) { return kernel.value(r, h); });
  };
  CHECK(value_of(kernel_type::cubic_spline) == cubic_spline<3>::value(r, h));
  CHECK(value_of(kernel_type::wendland_c2) == wendland_c2<3>::value(r, h));
  CHECK(value_of(kernel_type::wendland_c4) == wendland_c4<3>::value(r, h));
  CHECK(value_of(kernel_type::wendland_c6) == wendland_c6<3>::value(r, h));
  CHECK(value_of(kernel_type::wendland_c4) != value_of(kernel_type::wendland_c6));
}

TEST_CASE("dispatched kernel works inside a Kokkos reduction", "[kernels]") {
  // Sum of W over points on a line, once on the host loop and once in parallel_reduce.
  constexpr int count = 1000;
  const double h = 0.05;
  for (kernel_type type : all_kernel_types) {
    const double expected = dispatch_kernel<1>(type, [&](auto kernel) {
      double sum = 0.0;
      for (int i = 0; i < count; ++i) sum += kernel.value(i * 1e-4, h);
      return sum;
    });
    const double parallel = dispatch_kernel<1>(type, [&](auto kernel) {
      double sum = 0.0;
      Kokkos::parallel_reduce(
        "kernel_sum", Kokkos::RangePolicy<>(0, count),
        KOKKOS_LAMBDA(int i, double& partial) { partial += kernel.value(i * 1e-4, h); }, sum);
      return sum;
    });
    CHECK(parallel == Approx(expected).epsilon(1e-13));
  }
}
