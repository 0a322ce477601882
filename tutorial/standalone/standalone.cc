// A program outside the FleCSPH-lite tree, built against the installed framework and SPH
// specialization: the kernel normalization sum_i W(|x_i - x_0|, h) dx = 1 on a narray over ranks.
//
//   mpirun -np 2 standalone [--kernel wendland_c2] [--cells 4096]
#include "flecsi_lite/data.hh"
#include "flecsi_lite/execution.hh"
#include "flecsi_lite/runtime.hh"
#include "flecsi_lite/topology/narray.hh"
#include "specialization/physics.hh"

#include <cmath>

using namespace flecsi_lite;
using topology::narray;
namespace physics = flecsph::physics;

namespace {
// Each rank sums its own cells (cell centres x_i = (i + 1/2) dx) exactly; reduce adds the ranks.
util::exact_sum kernel_sum(const narray& mesh, physics::kernel_type type, double h) {
  const double dx = 1.0 / double(mesh.global_size());
  util::exact_sum sum;
  physics::dispatch_kernel<1>(type, [&](auto kernel) {
    for (std::size_t i = 0; i < mesh.owned_size(); ++i)
      sum.add(kernel.value(std::abs((double(mesh.global_index(i)) + 0.5) * dx - 0.5), h) * dx);
  });
  return sum;
}
}  // namespace

int main(int argc, char** argv) {
  runtime::options options("Standalone: the framework and the SPH kernels from an installed package.");
  options.value("kernel", "NAME", "cubic_spline, wendland_c2, wendland_c4 or wendland_c6", "wendland_c2")
    .value("cells", "N", "cells of the unit interval", "4096");
  runtime::runtime rt(argc, argv, options);
  if (!rt.proceed()) return rt.exit_code();
  const physics::kernel_type type = physics::kernel_from_name(rt.opts().get("kernel"));  // in the sph library
  narray mesh(std::stoul(rt.opts().get("cells")), 0, false);
  const double h = 0.01;  // the kernel reaches 2h = 0.02 from the centre: inside the interval
  const double total = reduce<kernel_sum, reduction::exact_sum>(mesh, type, h).get();
  const bool correct = std::abs(total - 1) < 1e-6;
  log::info() << physics::kernel_name(type) << " on " << runtime::size() << " rank(s): sum W dx = " << total;
  if (!correct) log::error() << "standalone: the kernel does not integrate to 1";
  return correct ? 0 : 1;
}
