// Plausibility bounds on what an HDF5 file declares, checked before anything is allocated: a
// corrupted or forged dataspace or datatype may declare far more elements than the file holds.
#pragma once

#include <hdf5.h>

#include <cstdint>
#include <string>

namespace flecsi_lite::io {

/// Largest ratio of logical to stored bytes a filtered (compressed) dataset can reach: deflate's
/// limit, 1032:1 (zlib technical details), above every other common HDF5 filter's.
inline constexpr std::uint64_t largest_compression_ratio = 1032;

/// The most elements of `element_size` bytes the dataset `dataset` of a file of `file_size`
/// bytes can hold: file_size / element_size without filters, times largest_compression_ratio
/// with filters. A declared extent above it is corruption.
std::uint64_t storable_elements(hid_t dataset, std::uint64_t element_size, std::uint64_t file_size);

/// The size in bytes of the file that holds `location` (any object of it); 0 when unknown (then no bound applies).
std::uint64_t file_size_of(hid_t location);

}  // namespace flecsi_lite::io
