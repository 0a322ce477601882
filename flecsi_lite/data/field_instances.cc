// The storage and registry entries of the common field element types, compiled once
// (field_storage.hh and field_registry.hh declare them extern): every topology holds such fields,
// so their code is generated here, not in each translation unit.
#include "flecsi_lite/data/field_registry.hh"
#include "flecsi_lite/data/field_storage.hh"

#include <array>
#include <cstdint>

namespace flecsi_lite::data {
template class field_storage<double>;
template class field_storage<std::uint64_t>;
template class field_storage<std::int64_t>;
template class field_storage<std::array<double, 1>>;
template class field_storage<std::array<double, 2>>;
template class field_storage<std::array<double, 3>>;

template registered_field make_registered_field<double>(std::string, data::persistence);
template registered_field make_registered_field<std::uint64_t>(std::string, data::persistence);
template registered_field make_registered_field<std::int64_t>(std::string, data::persistence);
template registered_field make_registered_field<std::array<double, 1>>(std::string, data::persistence);
template registered_field make_registered_field<std::array<double, 2>>(std::string, data::persistence);
template registered_field make_registered_field<std::array<double, 3>>(std::string, data::persistence);
}  // namespace flecsi_lite::data
