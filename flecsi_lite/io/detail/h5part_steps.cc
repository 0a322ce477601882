// Listing the steps of an H5Part file (see h5part_steps.hh).
#include "flecsi_lite/io/detail/h5part_steps.hh"

#include "flecsi_lite/io/detail/h5part_layout.hh"
#include "flecsi_lite/io/detail/hdf5_errors.hh"
#include "flecsi_lite/io/io_error.hh"

#include <algorithm>

namespace flecsi_lite::io::h5part {

namespace {
herr_t collect_name(hid_t, const char* name, const H5L_info_t*, void* names) {
  static_cast<std::vector<std::string>*>(names)->emplace_back(name);
  return 0;
}
}  // namespace

std::vector<std::int64_t> step_indices(const std::vector<std::string>& groups) {
  std::vector<std::int64_t> steps;
  for (const auto& name : groups)
    if (const auto index = parse_step_group_name(name)) steps.push_back(*index);
  std::sort(steps.begin(), steps.end());
  return steps;
}

std::vector<std::int64_t> step_indices(hid_t file) {
  std::vector<std::string> names;
  hsize_t position = 0;
  if (H5Literate(file, H5_INDEX_NAME, H5_ITER_INC, &position, collect_name, &names) < 0)
    throw io_error(failure::file, "cannot list the steps" + hdf5_reason());
  return step_indices(names);
}

}  // namespace flecsi_lite::io::h5part
