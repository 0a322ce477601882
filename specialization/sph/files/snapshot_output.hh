// The SPH particles as a series of SWIFT/GADGET-layout snapshots (snapshot_layout.hh): one file
// `<stem>_NNNN.hdf5` per output time beside output_file, each written collectively under a
// temporary name and renamed, then the XDMF index `<stem>.xdmf` of the series rewritten.
//
//   snapshot_series<D> series("sod.h5part", {program, parameters_text, units});
//   series.write(s);   // sod_0000.hdf5, sod.xdmf
#pragma once

#include "specialization/physics/kernels.hh"
#include "specialization/sph/files/snapshot_layout.hh"
#include "specialization/sph/model/fields.hh"
#include "specialization/sph/model/simulation.hh"

#include "flecsi_lite/app.hh"
#include "flecsi_lite/data.hh"
#include "flecsi_lite/execution.hh"
#include "flecsi_lite/io.hh"
#include "flecsi_lite/runtime.hh"

#include <algorithm>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <limits>
#include <sstream>
#include <string>
#include <variant>
#include <vector>

namespace flecsph::sph {

/// What every snapshot of a run says about the run.
struct snapshot_run {
  std::string program;
  std::string parameters_text;  ///< the resolved parameters ("key = value  # origin" lines)
  unit_system units;
};

/// `<stem>_NNNN.hdf5` and `<stem>.xdmf` beside output_file (`<program>` when there is none).
inline std::string snapshot_path(const std::string& output_file, const std::string& program, std::int64_t index) {
  char number[32];  // "_", 20 digits and a sign, ".hdf5", NUL
  std::snprintf(number, sizeof number, "_%04lld.hdf5", static_cast<long long>(index));
  return flecsi_lite::app::beside_output(output_file, program, number);
}
inline std::string snapshot_index_path(const std::string& output_file, const std::string& program) {
  return flecsi_lite::app::beside_output(output_file, program, ".xdmf");
}

/// Whether `path` is a snapshot or the index of the series of output_file (a file key naming one
/// would be overwritten).
inline bool names_snapshot_file(const std::string& path, const std::string& output_file, const std::string& program) {
  namespace fs = std::filesystem;
  if (path.empty()) return false;
  if (flecsi_lite::app::names_same_file(path, snapshot_index_path(output_file, program))) return true;
  const fs::path stem = fs::path(flecsi_lite::app::beside_output(output_file, program, ""));
  const fs::path candidate = fs::absolute(path).lexically_normal();
  if (candidate.parent_path() != fs::absolute(stem).lexically_normal().parent_path()) return false;
  std::string name = candidate.filename().string();
  if (name.size() > 8 && name.compare(name.size() - 8, 8, ".partial") == 0) name.resize(name.size() - 8);
  const std::string prefix = stem.filename().string() + "_", suffix = ".hdf5";
  if (name.size() < prefix.size() + 4 + suffix.size() || name.compare(0, prefix.size(), prefix) != 0 ||
      name.compare(name.size() - suffix.size(), suffix.size(), suffix) != 0)
    return false;
  const std::string digits = name.substr(prefix.size(), name.size() - prefix.size() - suffix.size());
  return std::all_of(digits.begin(), digits.end(), [](char c) { return c >= '0' && c <= '9'; });
}

namespace detail {
inline double rank_real(double value) { return value; }
inline std::uint64_t rank_count(std::uint64_t value) { return value; }

/// The owned values of H5Part dataset `name` (the registered field component it names, zeros for
/// a padding component) as doubles, or as they are for the ids.
template<int D>
flecsi_lite::data::value_buffer owned_dataset(simulation<D>& s, const std::string& name) {
  namespace data = flecsi_lite::data;
  const auto& fields = data::registered_fields<particle_tree<D>>();
  for (std::size_t id = 0; id < fields.size(); ++id) {
    const auto& f = fields[id];
    for (int k = 0; k < int(f.datasets.size()); ++k) {
      if (f.datasets[k] != name) continue;
      if (k < f.components) return f.owned_values(*s.particles, id, f.name, k);
      return std::vector<double>(s.particles->owned_size(), 0.0);
    }
  }
  throw std::logic_error("snapshot: no field writes the dataset '" + name + "'");
}

/// Rows `rows` of the sources' values, `sources.size()` columns, in the type of the first source.
template<int D>
flecsi_lite::data::value_buffer gather_rows(simulation<D>& s, const std::vector<std::string>& sources,
                                            const std::vector<std::size_t>& rows) {
  std::vector<flecsi_lite::data::value_buffer> columns;
  for (const auto& name : sources) columns.push_back(owned_dataset(s, name));
  return std::visit(
    [&](const auto& first) -> flecsi_lite::data::value_buffer {
      using E = typename std::decay_t<decltype(first)>::value_type;
      std::vector<E> out;
      out.reserve(rows.size() * columns.size());
      for (std::size_t row : rows)
        for (const auto& column : columns)
          out.push_back(std::visit([row](const auto& values) { return static_cast<E>(values[row]); }, column));
      return out;
    },
    columns.front());
}

/// "key = value  # origin" lines as (key, value).
inline flecsi_lite::io::snapshot_attributes parameter_attributes(const std::string& text) {
  flecsi_lite::io::snapshot_attributes out;
  std::istringstream lines(text);
  for (std::string line; std::getline(lines, line);) {
    const auto equals = line.find(" = ");
    if (line.empty() || line[0] == '#' || equals == std::string::npos) continue;
    std::string value = line.substr(equals + 3);
    if (const auto comment = value.find("  #"); comment != std::string::npos) value.resize(comment);
    while (!value.empty() && value.back() == ' ') value.pop_back();
    out.push_back({line.substr(0, equals), value});
  }
  return out;
}

/// The extent of the particles along each axis (1 where it is 0: an axis beyond D), or the fixed
/// box's sides. Collective.
template<int D>
std::vector<double> box_size(simulation<D>& s, const std::vector<double>& xyz) {
  std::vector<double> sides(3, 1.0);
  if (s.tree_settings.fixed_box) {
    for (int k = 0; k < D; ++k) sides[k] = s.tree_settings.fixed_box->hi[k] - s.tree_settings.fixed_box->lo[k];
    return sides;
  }
  double low[3], high[3];
  for (int k = 0; k < 3; ++k) low[k] = std::numeric_limits<double>::max(), high[k] = -low[k];
  for (std::size_t i = 0; i + 2 < xyz.size(); i += 3)
    for (int k = 0; k < 3; ++k) low[k] = std::min(low[k], xyz[i + k]), high[k] = std::max(high[k], xyz[i + k]);
  namespace reduction = flecsi_lite::reduction;
  for (int k = 0; k < 3; ++k) {
    const double lowest = flecsi_lite::reduce<rank_real, reduction::min>(low[k]).get();
    const double highest = flecsi_lite::reduce<rank_real, reduction::max>(high[k]).get();
    if (highest > lowest) sides[k] = highest - lowest;
  }
  return sides;
}
}  // namespace detail

template<int D>
class snapshot_series {
 public:
  snapshot_series(std::string output_file, snapshot_run run)
      : output_file_(std::move(output_file)), run_(std::move(run)) {}

  std::string path(std::int64_t index) const { return snapshot_path(output_file_, run_.program, index); }
  std::string index_path() const { return snapshot_index_path(output_file_, run_.program); }
  std::int64_t written() const { return static_cast<std::int64_t>(paths_.size()); }

  /// A restart at time t: keeps the series' snapshots 0, 1, ... that exist and precede t (or are
  /// at t when `keep_at_time`, the restart step's output having been due), so the next one
  /// continues the numbering. Collective.
  void continue_series(double time, bool keep_at_time) {
    std::uint64_t kept = 0;
    if (flecsi_lite::runtime::rank() == 0)
      for (;; ++kept) {
        if (!std::filesystem::is_regular_file(path(kept))) break;
        double t = 0;
        try {
          t = flecsi_lite::io::describe_snapshot(path(kept)).time;
        } catch (const flecsi_lite::io::io_error&) {
          break;
        }
        if (t > time || (t == time && !keep_at_time)) break;
      }
    kept = flecsi_lite::reduce<detail::rank_count, flecsi_lite::reduction::max>(kept).get();  // rank 0's
    for (std::uint64_t k = 0; k < kept; ++k) paths_.push_back(path(static_cast<std::int64_t>(k)));
  }

  /// Once the run has passed its checks (rank 0; the others do nothing): removes the snapshots
  /// `<stem>_NNNN.hdf5` an earlier run of this name left after the last one this run wrote
  /// (numbered on without a gap, each a FleCSPH-lite snapshot, Code/Code; anything else stops the
  /// removal and is named), so that no stale file passes for part of this series, and names them.
  /// A failed or interrupted run never gets here, so it removes nothing.
  void remove_stale_snapshots() {
    if (flecsi_lite::runtime::rank() != 0) return;
    for (std::int64_t k = written();; ++k) {
      const std::string file = path(k);
      std::error_code error;
      if (!std::filesystem::is_regular_file(file, error)) return;
      if (flecsi_lite::io::gadget_reader::text_attribute(file, "Code", "Code") != "FleCSPH-lite") {
        flecsi_lite::log::warn() << run_.program << ": '" << file << "' follows this run's snapshots but is not a "
                                 << "FleCSPH-lite snapshot: left in place";
        return;
      }
      if (!std::filesystem::remove(file, error) || error) {
        flecsi_lite::log::warn() << run_.program << ": cannot remove the stale snapshot '" << file
                                 << "' of an earlier run: " << error.message();
        return;
      }
      flecsi_lite::log::info() << run_.program << ": removed '" << file
                               << "', a snapshot of an earlier run beyond this series";
    }
  }

  /// Collective: the next snapshot at s.time, renamed into place, then the index.
  void write(simulation<D>& s) {
    flecsi_lite::wait_all();
    const std::string file = path(written());
    flecsi_lite::io::snapshot_writer out(file);
    const auto kinds = std::get<std::vector<std::int32_t>>(detail::owned_dataset(s, "kind"));
    std::vector<std::size_t> fluid, walls;
    for (std::size_t i = 0; i < kinds.size(); ++i)
      (kinds[i] == std::int32_t(particle_kind::wall) ? walls : fluid).push_back(i);
    namespace reduction = flecsi_lite::reduction;
    const std::uint64_t total[2] = {flecsi_lite::reduce<detail::rank_count, reduction::sum>(fluid.size()).get(),
                                    flecsi_lite::reduce<detail::rank_count, reduction::sum>(walls.size()).get()};
    std::vector<std::size_t> all(kinds.size());
    for (std::size_t i = 0; i < all.size(); ++i) all[i] = i;
    const auto xyz = std::get<std::vector<double>>(detail::gather_rows(s, {"x", "y", "z"}, all));

    write_metadata(out, s, {total[0], total[1]}, detail::box_size(s, xyz));
    write_type(out, s, fluid_part_type, fluid, false);
    if (total[1] > 0) write_type(out, s, wall_part_type, walls, true);
    out.close();
    paths_.push_back(file);
    flecsi_lite::io::write_xdmf_index(flecsi_lite::runtime::communicator(), index_path(), paths_);
  }

 private:
  void write_type(flecsi_lite::io::snapshot_writer& out, simulation<D>& s, int type,
                  const std::vector<std::size_t>& rows, bool walls) {
    const std::string group = part_type_group(type);
    for (const auto& q : snapshot_quantities<D>(s, walls)) {
      const auto values = detail::gather_rows(s, q.sources, rows);
      const int columns = static_cast<int>(q.sources.size());
      std::visit([&](const auto& v) { out.write(group, q.name, v, columns, unit_attributes(run_.units, q)); }, values);
    }
  }

  void write_metadata(flecsi_lite::io::snapshot_writer& out, simulation<D>& s, const std::vector<std::uint64_t>& counts,
                      const std::vector<double>& box) {
    using ints = std::vector<std::int32_t>;
    using doubles = std::vector<double>;
    std::vector<std::int64_t> this_file(part_type_count, 0);
    std::vector<std::uint32_t> low(part_type_count, 0), high(part_type_count, 0);
    ints can_have(part_type_count, 0);
    const int types[2] = {fluid_part_type, wall_part_type};
    for (int k = 0; k < 2; ++k) {
      this_file[types[k]] = static_cast<std::int64_t>(counts[k]);
      low[types[k]] = static_cast<std::uint32_t>(counts[k] & 0xffffffffu);
      high[types[k]] = static_cast<std::uint32_t>(counts[k] >> 32);
      can_have[types[k]] = counts[k] > 0 || k == 0;
    }
    const std::vector<std::uint32_t> no_flags(part_type_count, 0);
    // GADGET-2's header (user guide table 4) with SWIFT's additions (parallel_io.c, write_output_parallel).
    out.set_attributes("Header", {{"BoxSize", box},
                                  {"Time", doubles{s.time}},
                                  {"Dimension", ints{D}},
                                  {"Redshift", doubles{0}},
                                  {"Scale-factor", doubles{1}},
                                  // The layout's name, by which yt recognises it; the writer is in group Code.
                                  {"Code", std::string("SWIFT")},
                                  {"RunName", run_.program + " (FleCSPH-lite)"},
                                  {"NumPart_ThisFile", this_file},
                                  {"NumPart_Total", low},
                                  {"NumPart_Total_HighWord", high},
                                  {"TotalNumberOfParticles", this_file},
                                  {"MassTable", doubles(part_type_count, 0.0)},
                                  {"InitialMassTable", doubles(part_type_count, 0.0)},
                                  {"Flag_Entropy_ICs", no_flags},
                                  {"Flag_Sfr", ints{0}},
                                  {"Flag_Cooling", ints{0}},
                                  {"Flag_Feedback", ints{0}},
                                  {"Flag_StellarAge", ints{0}},
                                  {"Flag_Metals", ints{0}},
                                  {"Flag_DoublePrecision", ints{1}},
                                  {"Omega0", doubles{0}},
                                  {"OmegaLambda", doubles{0}},
                                  {"HubbleParam", doubles{1}},
                                  {"NumFilesPerSnapshot", ints{1}},
                                  {"ThisFile", ints{0}},
                                  {"Virtual", ints{0}},
                                  {"CanHaveTypes", can_have},
                                  {"OutputType", std::string("FullVolume")},
                                  {"Iteration", std::vector<std::int64_t>{s.step}},
                                  {"TimeStep", doubles{s.dt}}});
    out.set_attributes("Units", units_group(run_.units));
    out.set_attributes("InternalCodeUnits", units_group(run_.units));
    out.set_attributes("Cosmology", {{"Cosmological run", ints{0}},
                                     {"Redshift", doubles{0}},
                                     {"Scale-factor", doubles{1}},
                                     {"H0 [internal units]", doubles{0}},
                                     {"h", doubles{1}}});
    out.set_attributes("HydroScheme", {{"Scheme", std::string("SPH (FleCSPH-lite)")},
                                       {"Kernel function", std::string(physics::kernel_name(s.physics.kernel))},
                                       {"Kernel support radius over h", doubles{physics::kernel_support}},
                                       {"Adiabatic index", doubles{s.physics.eos.ideal.gamma}},
                                       {"Dimension", ints{D}}});
    out.set_attributes("SubgridScheme", {});  // none, but yt opens it
    // SWIFT's engine policies, which yt and pynbody take as the mark of a SWIFT snapshot.
    out.set_attributes("Policy", {{"hydro", ints{1}},
                                  {"self gravity", ints{s.physics.gravity.enabled}},
                                  {"external gravity", ints{0}},
                                  {"cosmological integration", ints{0}}});
    // Our keys, and SWIFT's InitialConditions:periodic that yt reads (1 when any axis is periodic).
    auto parameters = detail::parameter_attributes(run_.parameters_text);
    const bool periodic =
      std::any_of(s.tree_settings.periodic.begin(), s.tree_settings.periodic.end(), [](bool p) { return p; });
    parameters.push_back({"InitialConditions:periodic", std::string(periodic ? "1" : "0")});
    out.set_attributes("Parameters", parameters);
    out.set_attributes("Code", {{"Code", std::string("FleCSPH-lite")},
                                {"Code Version", std::string(flecsi_lite::app::version())},
                                {"Git Revision", std::string(flecsi_lite::app::git_describe())},
                                {"Program", run_.program}});
  }

  std::string output_file_;
  snapshot_run run_;
  std::vector<std::string> paths_;  // the series so far, in order
};

}  // namespace flecsph::sph
