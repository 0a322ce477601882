// The SPH specialization's public face, the one header an SPH app includes: the app frame
// (sph/run/app.hh: configuration, initial data, output, checkpoints, statistics, main()), the
// standard control model with its force evaluation stage (sph/step/), the task vocabulary and
// fields (sph/model/), the files (sph/files/) and the problem checks (sph/run/problem_checks.hh).
// The rooms under sph/ are its inside: apps and the tutorial include this header (tests/layout).
#pragma once

#include "specialization/sph/run/app.hh"
#include "specialization/sph/run/problem_checks.hh"
