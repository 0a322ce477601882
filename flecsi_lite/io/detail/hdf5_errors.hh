// HDF5's error stack, made quiet: HDF5 prints nothing while a hdf5_quiet_scope lives, and the
// innermost reason of the last failure can be read back to build a clean message.
#pragma once

#include <hdf5.h>

#include <string>

namespace flecsi_lite::io {

/// Turns off HDF5's automatic printing of its error stack for the lifetime of the object and
/// restores the previous handler afterwards.
class hdf5_quiet_scope {
 public:
  hdf5_quiet_scope();
  hdf5_quiet_scope(const hdf5_quiet_scope&) = delete;
  hdf5_quiet_scope& operator=(const hdf5_quiet_scope&) = delete;
  ~hdf5_quiet_scope();

 private:
  H5E_auto2_t previous_function_ = nullptr;
  void* previous_data_ = nullptr;
};

/// The most specific description on HDF5's current error stack (e.g. "truncated file: eof =
/// ..."), or "" when the stack is empty.
std::string hdf5_error_detail();

/// " (HDF5: <detail>)", or "" when HDF5 recorded nothing: appended to our own messages.
std::string hdf5_reason();

}  // namespace flecsi_lite::io
