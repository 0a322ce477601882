// The ids of initial particles, checked when they are read (issue 38, item 4): an id that is not
// a whole number >= 0 (NaN, 1.5, -3 in a float or signed dataset) or that two particles share
// would break the (key, id) order of every neighbour sum and make a checkpoint its own restart
// refuses. Without an id dataset the ids are the particles' indices, unique by construction.
#pragma once

#include "flecsi_lite/io.hh"

#include <cmath>
#include <cstdint>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace flecsph::sph::detail {

/// Collective: throws io::layout_error on every rank (exit status 3), naming the file and the
/// dataset, when an id of `in` (column "id", any numeric type) is not a whole number in [0, 2^64)
/// or is shared by two particles (the smallest such id).
inline void check_initial_ids(const flecsi_lite::io::column_source& in) {
  namespace io = flecsi_lite::io;
  if (!in.has_column("id")) return;
  const std::string where = in.where() + " dataset 'id'";
  const auto type = in.column_type("id");
  // block() is collective: taken once here, never inside refuse(), which only the ranks holding
  // a bad id run (calling it there left the other ranks in the next collective: a hang at 2 ranks).
  const io::slice mine = in.block();
  std::vector<std::uint64_t> ids(mine.count);
  std::optional<io::failure_record> failed;
  const auto refuse = [&](std::size_t a, const std::string& value) {
    if (failed) return;
    failed =
      io::failure_record{io::failure::layout, where + " holds " + value + " for the particle at index " +
                                                std::to_string(mine.offset + a) + ": ids must be whole numbers >= 0"};
  };
  if (type == io::element_type::float64 || type == io::element_type::float32) {
    const auto values = in.read<double>("id");
    for (std::size_t a = 0; a < values.size(); ++a) {
      const double id = values[a];
      if (!(id >= 0 && id < 18446744073709551616.0 && std::floor(id) == id)) {
        std::ostringstream text;
        text.precision(17);
        text << id;
        refuse(a, text.str());
      } else
        ids[a] = static_cast<std::uint64_t>(id);
    }
  } else if (type == io::element_type::uint64) {
    ids = in.read<std::uint64_t>("id");
  } else {
    const auto values = in.read<std::int64_t>("id");
    for (std::size_t a = 0; a < values.size(); ++a)
      if (values[a] < 0)
        refuse(a, std::to_string(values[a]));
      else
        ids[a] = static_cast<std::uint64_t>(values[a]);
  }
  io::raise_if_any(in.communicator(), failed);
  if (const auto twice = io::duplicate_id(ids.data(), ids.size(), in.communicator()))
    throw io::layout_error(where + ": id " + std::to_string(*twice) +
                           " belongs to more than one particle: each particle needs its own id");
}

}  // namespace flecsph::sph::detail
