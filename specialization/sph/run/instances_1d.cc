// The SPH step and the app frame for D = 1, compiled once (instances.hh).
#include "specialization/sph/run/app.hh"

namespace flecsph::sph {
FLECSPH_SPH_STEP_INSTANCES(, 1)
FLECSPH_SPH_APP_INSTANCES(, 1)
}  // namespace flecsph::sph
