// The hydrostatic start in the equilibrium of the SPH equations themselves, not only of the
// continuum: with P(y) of the continuum at the particles, the SPH pressure force misses gravity
// by up to 6 g at the interface (32 particles per unit length; 2 g at 64: the density varies over
// Delta ~ h, and the pressure term P / rho^2 is large against g rho h), whose waves are as large
// as the seed. Here each fluid row's pressure is solved for so that its SPH acceleration (the
// force task's sum, Price 2012 eqs. 30-35, with its kernel, h = eta (m / rho)^(1/2) and Omega) is
// exactly zero with gravity; the walls keep the continuum's P(y). The rows are periodic lattices
// of one count (every particle of a row has the same neighbourhood), so the sums are over rows.
#pragma once

#include "rayleigh_taylor_problem.hh"

#include <vector>

namespace rayleigh_taylor {

/// A row's density, smoothing length, grad-h factor and pressure as the SPH sums give them.
struct row_state {
  double rho = 0, h = 0, omega = 1, pressure = 0;
};

/// The state of every row of `rows` (one count per row; walls: h from the profile's density,
/// Omega = 1, P = P(y); fluid: adaptive h, and P solved for zero SPH acceleration).
std::vector<row_state> discrete_equilibrium(const std::vector<row>& rows, double mass, const problem& problem,
                                            const sph::physics_settings& physics);

}  // namespace rayleigh_taylor
