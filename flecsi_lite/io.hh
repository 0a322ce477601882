// Parallel HDF5 I/O in the H5Part layout, its public face: writer, reader, checkpoints, ASCII
// export for splash, the errors every reader and writer throws, where each rank's particles lie
// in a file, attribute values and element types, collective agreement on failures and the checks
// of the paths writers replace. The HDF5 plumbing (handles, property lists, attributes, the error
// stack) lives in io/hdf5/.
#pragma once
#include "flecsi_lite/io/ascii_columns.hh"
#include "flecsi_lite/io/attribute_value.hh"
#include "flecsi_lite/io/checkpoint.hh"
#include "flecsi_lite/io/collective_agreement.hh"
#include "flecsi_lite/io/column_source.hh"
#include "flecsi_lite/io/element_type.hh"
#include "flecsi_lite/io/field_io.hh"
#include "flecsi_lite/io/gadget_reader.hh"
#include "flecsi_lite/io/h5part_reader.hh"
#include "flecsi_lite/io/h5part_writer.hh"
#include "flecsi_lite/io/io_error.hh"
#include "flecsi_lite/io/output_path.hh"
#include "flecsi_lite/io/particle_partition.hh"
#include "flecsi_lite/io/run_state_checksums.hh"
#include "flecsi_lite/io/snapshot_writer.hh"
#include "flecsi_lite/io/step_info.hh"
#include "flecsi_lite/io/xdmf_index.hh"
