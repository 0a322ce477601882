// Parallel HDF5 I/O in the H5Part layout: writer, reader, checkpoints, ASCII export for splash.
#pragma once
#include "flecsi_lite/io/ascii_columns.hh"
#include "flecsi_lite/io/checkpoint.hh"
#include "flecsi_lite/io/h5part_reader.hh"
#include "flecsi_lite/io/h5part_writer.hh"
