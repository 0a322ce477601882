// The exact solutions the apps and tests compare with: the Riemann problem (Sod), the
// Sedov-Taylor blast wave, and the channel flows (Poiseuille, Couette) (specialization/analytic/).
#pragma once

#include "specialization/analytic/channel_flow.hh"
#include "specialization/analytic/quadrature.hh"
#include "specialization/analytic/riemann_exact.hh"
#include "specialization/analytic/sedov_taylor.hh"
