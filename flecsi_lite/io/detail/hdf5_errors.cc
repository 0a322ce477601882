// Quiet HDF5 error handling and extraction of HDF5's own reason for a failure.
#include "flecsi_lite/io/detail/hdf5_errors.hh"

namespace flecsi_lite::io {

hdf5_quiet_scope::hdf5_quiet_scope() {
  H5Eget_auto2(H5E_DEFAULT, &previous_function_, &previous_data_);
  H5Eset_auto2(H5E_DEFAULT, nullptr, nullptr);
}

hdf5_quiet_scope::~hdf5_quiet_scope() { H5Eset_auto2(H5E_DEFAULT, previous_function_, previous_data_); }

namespace {
// Walking downward visits the API call first and the lowest-level cause last.
herr_t keep_last_description(unsigned, const H5E_error2_t* error, void* client) {
  if (error->desc && *error->desc) *static_cast<std::string*>(client) = error->desc;
  return 0;
}
}  // namespace

std::string hdf5_error_detail() {
  std::string detail;
  H5Ewalk2(H5E_DEFAULT, H5E_WALK_DOWNWARD, keep_last_description, &detail);
  return detail;
}

std::string hdf5_reason() {
  const std::string detail = hdf5_error_detail();
  return detail.empty() ? std::string() : " (HDF5: " + detail + ")";
}

}  // namespace flecsi_lite::io
