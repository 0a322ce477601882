// Ownership of one HDF5 identifier (file, group, dataset, dataspace, attribute, datatype or
// property list): closed exactly once, when the handle is reset or destroyed.
#pragma once

#include <hdf5.h>

#include <utility>

namespace flecsi_lite::io {

class hdf5_handle {
 public:
  using closer = herr_t (*)(hid_t);

  hdf5_handle() = default;
  /// Takes `id` (negative: the failed result of an HDF5 call, held as an invalid handle).
  hdf5_handle(hid_t id, closer close_function) : id_(id), close_(close_function) {}
  hdf5_handle(const hdf5_handle&) = delete;
  hdf5_handle& operator=(const hdf5_handle&) = delete;
  hdf5_handle(hdf5_handle&& other) noexcept : id_(std::exchange(other.id_, H5I_INVALID_HID)), close_(other.close_) {}
  hdf5_handle& operator=(hdf5_handle&& other) noexcept {
    if (this != &other) {
      reset();
      id_ = std::exchange(other.id_, H5I_INVALID_HID);
      close_ = other.close_;
    }
    return *this;
  }
  ~hdf5_handle() { reset(); }

  hid_t get() const { return id_; }
  bool valid() const { return id_ >= 0; }
  explicit operator bool() const { return valid(); }

  /// Closes now; returns HDF5's status (negative on failure), 0 when there was nothing to close.
  herr_t close() {
    herr_t status = 0;
    if (valid() && close_) status = close_(id_);
    id_ = H5I_INVALID_HID;
    return status;
  }
  void reset() { close(); }

  /// Gives up ownership without closing (used when a collective close cannot be made safely).
  hid_t release() { return std::exchange(id_, H5I_INVALID_HID); }

 private:
  hid_t id_ = H5I_INVALID_HID;
  closer close_ = nullptr;
};

inline hdf5_handle file_handle(hid_t id) { return {id, H5Fclose}; }
inline hdf5_handle group_handle(hid_t id) { return {id, H5Gclose}; }
inline hdf5_handle dataset_handle(hid_t id) { return {id, H5Dclose}; }
inline hdf5_handle dataspace_handle(hid_t id) { return {id, H5Sclose}; }
inline hdf5_handle attribute_handle(hid_t id) { return {id, H5Aclose}; }
inline hdf5_handle datatype_handle(hid_t id) { return {id, H5Tclose}; }
inline hdf5_handle property_list_handle(hid_t id) { return {id, H5Pclose}; }
inline hdf5_handle object_handle(hid_t id) { return {id, H5Oclose}; }

}  // namespace flecsi_lite::io
