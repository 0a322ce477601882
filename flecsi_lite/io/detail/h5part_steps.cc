// Listing the steps of an H5Part file (see h5part_steps.hh).
#include "flecsi_lite/io/detail/h5part_steps.hh"

#include "flecsi_lite/io/detail/h5part_layout.hh"
#include "flecsi_lite/io/detail/hdf5_errors.hh"
#include "flecsi_lite/io/io_error.hh"

#include <algorithm>

namespace flecsi_lite::io::h5part {

namespace {
herr_t collect_step(hid_t, const char* name, const H5L_info_t*, void* steps) {
  if (const auto index = parse_step_group_name(name)) static_cast<std::vector<std::int64_t>*>(steps)->push_back(*index);
  return 0;
}
}  // namespace

std::vector<std::int64_t> step_indices(hid_t file) {
  std::vector<std::int64_t> steps;
  hsize_t position = 0;
  if (H5Literate(file, H5_INDEX_NAME, H5_ITER_INC, &position, collect_step, &steps) < 0)
    throw io_error(failure::file, "cannot list the steps" + hdf5_reason());
  std::sort(steps.begin(), steps.end());
  return steps;
}

}  // namespace flecsi_lite::io::h5part
