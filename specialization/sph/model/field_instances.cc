// The storage and registry entry of the particle kind field, compiled once (fields.hh declares
// them extern), as the framework does for its common element types (data/field_instances.cc).
#include "specialization/sph/model/fields.hh"

template class flecsi_lite::data::field_storage<flecsph::sph::particle_kind>;
template flecsi_lite::data::registered_field flecsi_lite::data::make_registered_field<flecsph::sph::particle_kind>(
  std::string, flecsi_lite::data::persistence);
