// Export of one H5Part step as whitespace-separated ASCII columns in the form splash reads
// (`splash -f ascii`, Price 2007, PASA 24, 159): a comment line that starts with the time, a
// comment line with the column names, then one row per particle.
#pragma once

#include "flecsi_lite/io/h5part_reader.hh"

#include <cstdint>
#include <ostream>
#include <string>
#include <vector>

namespace flecsi_lite::io {

/// Collective over the reader's communicator; every rank reads whole columns, so use a reader
/// on MPI_COMM_SELF (one process) for large files. Doubles are written with 17 significant
/// digits (they read back exactly), floats with 9, integers as integers. Throws the reader's
/// errors for a missing step or column (the latter with the nearest column name).
void write_ascii_columns(const h5part_reader& reader, std::int64_t step, const std::vector<std::string>& columns,
                         std::ostream& out);

/// The columns of `preferred` that the step has, in that order; all its datasets (in name
/// order) when it has none of them.
std::vector<std::string> available_columns(const h5part_reader& reader, std::int64_t step,
                                           const std::vector<std::string>& preferred);

}  // namespace flecsi_lite::io
