// The twin launch that hides communication (DESIGN.md, "Overlap in the step"): a pair task is
// launched over the INTERIOR targets, whose neighbours are all owned (Ghost = na: it waits for no
// ghost copy, so it runs while the copies travel), then over the BOUNDARY targets, some of whose
// neighbours are ghosts (Ghost = ro: after the copies). Each target's sums run in one launch in
// its canonical order, so the split changes no bit of any result (neighbourhood::targets).
#pragma once

#include "flecsi_lite/data.hh"
#include "flecsi_lite/execution.hh"

namespace flecsph::sph {

/// Launches `interior` with `start` as its initial value, then reduces with Reduction over the
/// ranks `boundary`, which starts from the interior launch's value: the future of the whole.
/// Both tasks take (neighbours, settings, initial value, fields...).
template<auto interior, auto boundary, class Reduction, class Neighbours, class Settings, class Start, class... Fields>
auto reduce_interior_then_boundary(Neighbours& neighbours, const Settings& settings, Start start, Fields... fields) {
  auto interior_value = flecsi_lite::execute<interior>(neighbours, settings, start, fields...);
  return flecsi_lite::reduce<boundary, Reduction>(neighbours, settings, interior_value, fields...);
}

}  // namespace flecsph::sph
