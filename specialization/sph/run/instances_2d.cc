// The SPH step and the app frame for D = 2, compiled once (instances.hh).
#include "specialization/sph/run/app.hh"

namespace flecsph::sph {
FLECSPH_SPH_STEP_INSTANCES(, 2)
FLECSPH_SPH_APP_INSTANCES(, 2)
}  // namespace flecsph::sph
