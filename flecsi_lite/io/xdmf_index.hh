// The XDMF index of a series of snapshot files (XDMF 2 model: a temporal collection of spatial
// collections of polyvertex grids, the way SWIFT's xmf.c describes its snapshots), which ParaView
// and VisIt open as one time series with the snapshots' times.
//
//   io::write_xdmf_index(comm, "run.xdmf", {"run_0000.hdf5", "run_0001.hdf5"});
//
// Vocabulary. Each snapshot becomes one time step; each root group of it that holds a dataset
// named `coordinates` (N x 3) becomes one grid of N points, its other N or N x C datasets the
// grid's point arrays (scalars, or vectors when C = 3). The files are read back to write the
// index, so it describes exactly what is on disk.
#pragma once

#include <mpi.h>

#include <cstdint>
#include <string>
#include <vector>

namespace flecsi_lite::io {

/// Where a snapshot keeps its time and its particle positions.
struct snapshot_series_layout {
  std::string time_group = "Header";
  std::string time_attribute = "Time";
  std::string coordinates = "Coordinates";
};

/// One dataset of a grid: its name, rows, columns (1 for N) and element type.
struct xdmf_array {
  std::string name;
  std::uint64_t rows = 0;
  int columns = 1;
  std::string number_type;  // "Float", "Int" or "UInt"
  int precision = 8;        // bytes
};
struct xdmf_grid {
  std::string group;
  std::uint64_t points = 0;
  std::vector<xdmf_array> arrays;  // the coordinates first
};
struct snapshot_description {
  double time = 0;
  std::vector<xdmf_grid> grids;
};

/// Serial: opens `path` (serial HDF5) and reads its time and grids. Throws io_error naming the
/// file when it cannot be read or lacks the time attribute.
snapshot_description describe_snapshot(const std::string& path, const snapshot_series_layout& layout = {});

/// The index's text for `snapshots` (described by describe_snapshot), each named by `file_names`
/// (as the index refers to them: relative to the index's folder).
std::string xdmf_text(const std::vector<snapshot_description>& snapshots, const std::vector<std::string>& file_names);

/// Collective: rank 0 describes every snapshot in `paths` and writes the index to `index_path`
/// atomically (write_text_file: `<index>.partial`, then renamed), naming the files relative to
/// the index's folder; every rank throws the same io_error when that fails.
void write_xdmf_index(MPI_Comm comm, const std::string& index_path, const std::vector<std::string>& paths,
                      const snapshot_series_layout& layout = {});

}  // namespace flecsi_lite::io
