// Pressure and velocity gauges (gauge_settings.hh): at each sample point X the Shepard-normalised
// SPH interpolation over the fluid particles b,
//   f(X) = sum_b V_b f_b W(X - x_b, h_b) / sum_b V_b W(X - x_b, h_b),   V_b = m_b / rho_b,
// and a gauge's value is the mean over its face's samples, a dry sample (no fluid within 2 h_b)
// counting as zero: a pressure sensor reads the force on its whole face. On a wall the face lies
// on the wall's surface, so the samples see the fluid on one side only; the Shepard denominator
// normalises that truncated kernel (Adami et al. 2012 extrapolate the walls' pressure the same
// way). Each rank sums its owned particles into exact sums (util::exact_sum), so a gauge is
// bitwise the same on any rank count.
#pragma once

#include "specialization/fluid/gauge_settings.hh"

#include "specialization/physics/kernels/kernel_at.hh"
#include "specialization/sph/model/tasks.hh"

#include "specialization/physics/kernels.hh"

#include "flecsi_lite/execution.hh"
#include "flecsi_lite/util.hh"

#include <array>
#include <cmath>
#include <vector>

namespace flecsph::fluid {

/// The sums of one sample point.
struct gauge_sums {
  flecsi_lite::util::exact_sum weight, pressure;
  std::array<flecsi_lite::util::exact_sum, 3> velocity;
};
struct gauge_reduction {
  static gauge_sums combine(gauge_sums a, const gauge_sums& b) {
    a.weight += b.weight, a.pressure += b.pressure;
    for (int k = 0; k < 3; ++k) a.velocity[k] += b.velocity[k];
    return a;
  }
};

/// This rank's sums at `point` over its owned fluid particles.
template<int D>
gauge_sums gauge_point_task(sph::vector<D> point, physics::kernel_type kernel_type, double smoothing,
                            sph::ro<sph::vector<D>> x, sph::ro<sph::vector<D>> v, sph::ro<double> m,
                            sph::ro<double> rho, sph::ro<double> P, sph::ro<double> h,
                            sph::ro<sph::particle_kind> kind) {
  gauge_sums s;
  physics::dispatch_kernel<D>(kernel_type, [&](auto kernel_type_tag) {
    using Kernel = decltype(kernel_type_tag);
    for (std::size_t b = 0; b < x.size(); ++b) {
      if (kind(b) != sph::particle_kind::fluid) continue;
      double r2 = 0;
      for (int k = 0; k < D; ++k) r2 += (point[k] - x(b)[k]) * (point[k] - x(b)[k]);
      const double h_b = smoothing * h(b), reach = physics::kernel_support * h_b;
      if (r2 >= reach * reach) continue;
      double w, dw_dh;
      sph::kernel_at<Kernel>(h_b).value_and_h_derivative(std::sqrt(r2), w, dw_dh);
      const double weight = m(b) / rho(b) * w;
      s.weight.add(weight);
      s.pressure.add(weight * P(b));
      for (int k = 0; k < D; ++k) s.velocity[k].add(weight * v(b)[k]);
    }
  });
  return s;
}

/// A gauge's reading: the mean pressure and velocity over its face's samples.
template<int D>
struct gauge_reading {
  double pressure = 0;
  sph::vector<D> velocity{};
};

/// The sample points of a face from `first` to `last` (already in the code's units): the
/// midpoints of `samples` equal parts, or the point itself. `third` is z in 3D.
template<int D>
std::vector<sph::vector<D>> gauge_samples(const std::array<double, 2>& first, const std::array<double, 2>& last,
                                          std::int64_t samples, double third) {
  const bool point = first == last;
  const std::int64_t n = point ? 1 : samples;
  std::vector<sph::vector<D>> out(static_cast<std::size_t>(n));
  for (std::int64_t i = 0; i < n; ++i) {
    const double s = point ? 0.0 : (double(i) + 0.5) / double(n);
    auto& p = out[static_cast<std::size_t>(i)];
    for (int k = 0; k < 2; ++k) p[k] = first[k] + s * (last[k] - first[k]);
    if constexpr (D == 3) p[2] = third;
  }
  return out;
}

/// Reads every gauge (one exact-sum reduction per sample, launched together), collective;
/// `smoothing` scales each particle's h in the interpolation (gauge_settings::smoothing).
template<int D, class State>
std::vector<gauge_reading<D>> read_gauges(State& s, const std::vector<std::vector<sph::vector<D>>>& gauges,
                                          double smoothing) {
  using f = sph::fields<D>;
  auto& p = *s.particles;
  using future = decltype(flecsi_lite::reduce<gauge_point_task<D>, gauge_reduction>(
    sph::vector<D>{}, s.physics.kernel, 1.0, f::position()(p), f::velocity(p), f::mass()(p), f::density(p),
    f::pressure(p), f::smoothing_length()(p), f::kind(p)));
  std::vector<std::vector<future>> pending(gauges.size());
  for (std::size_t g = 0; g < gauges.size(); ++g)
    for (const auto& point : gauges[g])
      pending[g].push_back(flecsi_lite::reduce<gauge_point_task<D>, gauge_reduction>(
        point, s.physics.kernel, smoothing, f::position()(p), f::velocity(p), f::mass()(p), f::density(p),
        f::pressure(p), f::smoothing_length()(p), f::kind(p)));
  std::vector<gauge_reading<D>> out(gauges.size());
  for (std::size_t g = 0; g < gauges.size(); ++g) {
    for (auto& sample : pending[g]) {
      const gauge_sums sums = sample.get();
      const double weight = sums.weight.value();
      if (!(weight > 0)) continue;  // dry: no fluid within reach
      out[g].pressure += sums.pressure.value() / weight;
      for (int k = 0; k < D; ++k) out[g].velocity[k] += sums.velocity[k].value() / weight;
    }
    const double n = double(pending[g].size());
    out[g].pressure /= n;
    for (int k = 0; k < D; ++k) out[g].velocity[k] /= n;
  }
  return out;
}

}  // namespace flecsph::fluid
