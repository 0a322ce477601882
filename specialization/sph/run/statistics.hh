// The statistics file of an SPH run, as SWIFT's statistics.txt and Phantom's .ev: one row every
// statistics_every steps (time, dt, the exact conserved totals of conserved.hh, mass, the mean
// neighbour count) under a header naming each column and its unit; rank 0 writes it, flushed row by row.
//
//   statistics_settings keys = statistics_parameters().read(p);    // statistics_file, statistics_every
//   s.statistics.open(path, header, std::nullopt);                // a new run (a restart: its step)
//   s.statistics.write(statistics_line<D>(s.step, s.time, dt, totals, neighbours));
//
// Vocabulary: a *row* is one line of numbers (the state after a step); the *column line* is the
// last header line, the columns' names separated by spaces, that a restart checks and keeps.
#pragma once

#include "specialization/sph/model/conserved.hh"

#include "flecsi_lite/io.hh"
#include "flecsi_lite/runtime.hh"

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace flecsph::sph {

/// The keys statistics_file and statistics_every.
struct statistics_settings {
  /// "auto": <output stem>.statistics.txt (<program>.statistics.txt without output); empty: none.
  std::string file = "auto";
  long every = 1;  ///< steps between rows; the first and the last step always have one
};

inline const flecsi_lite::runtime::parameter_block<statistics_settings>& statistics_parameters() {
  static const auto block = [] {
    flecsi_lite::runtime::parameter_block<statistics_settings> keys;
    keys.file("statistics_file", &statistics_settings::file,
              "one line per step of the conserved totals (auto: <output stem>.statistics.txt; none: off)");
    keys.integer("statistics_every", &statistics_settings::every, "steps between lines of statistics_file").at_least(1);
    return keys;
  }();
  return block;
}

/// One column: its name in the column line, what it holds and its unit (L, M, T: the code units).
struct statistics_column {
  std::string name, meaning, unit;
};

/// The columns; with self-gravity (`gravity`) a potential energy column after the internal one;
/// an app's own columns (`extra`) last.
template<int D>
std::vector<statistics_column> statistics_columns(bool gravity = false,
                                                  const std::vector<statistics_column>& extra = {}) {
  static const char* axes[] = {"x", "y", "z"};
  std::vector<statistics_column> columns = {
    {"step", "step number", "1"},
    {"time", "simulation time", "T"},
    {"dt", "time step that reached this row (0 in the first row of a run)", "T"},
    {"kinetic", "kinetic energy, sum of m v^2 / 2 over the fluid particles", "M L^2 T^-2"},
    {"internal", "internal energy, sum of m u over the fluid particles", "M L^2 T^-2"},
    {"walls", "energy the wall particles received (work of the fluid on them)", "M L^2 T^-2"},
    {"total", "total energy, kinetic + internal + walls, summed exactly", "M L^2 T^-2"}};
  if (gravity) {
    columns.insert(columns.begin() + 5,
                   {"potential", "gravitational energy W = 1/2 sum m Phi (self terms included)", "M L^2 T^-2"});
    columns.back().meaning = "total energy E = kinetic + internal + potential + walls, summed exactly";
  }
  for (int k = 0; k < D; ++k)
    columns.push_back({std::string("momentum_") + axes[k], "linear momentum (walls' impulse included)", "M L T^-1"});
  const char* angular_axes[] = {D == 2 ? "z" : "x", "y", "z"};
  for (int k = 0; k < angular_components<D>; ++k)
    columns.push_back(
      {std::string("angular_momentum_") + angular_axes[k], "angular momentum about the origin", "M L^2 T^-1"});
  columns.push_back({"mass", "mass of the fluid particles", "M"});
  columns.push_back({"mean_neighbours", "neighbours per particle, mean over all particles", "1"});
  columns.insert(columns.end(), extra.begin(), extra.end());
  return columns;
}

/// The header: `description` lines, each column with its meaning and unit, then the column line.
template<int D>
std::string statistics_header(const std::vector<std::string>& description, bool gravity = false,
                              const std::vector<statistics_column>& extra = {}) {
  std::ostringstream out;
  for (const auto& line : description) out << "# " << line << "\n";
  out << "# columns (code units: L, M, T are the units of length, mass and time the parameters use):\n";
  const auto columns = statistics_columns<D>(gravity, extra);
  std::string names;
  for (std::size_t c = 0; c < columns.size(); ++c) {
    out << "# " << std::setw(3) << c + 1 << " " << columns[c].name << " [" << columns[c].unit
        << "]: " << columns[c].meaning << "\n";
    names += (c ? " " : "") + columns[c].name;
  }
  out << "# " << names << "\n";
  return out.str();
}

/// One row, every real with 17 significant digits (read back exactly); the potential energy with
/// self-gravity (`gravity`, as in the header); the values of an app's own columns (`extra`) last.
template<int D>
std::string statistics_line(long step, double time, double dt, const conserved_totals<D>& t, double mean_neighbours,
                            bool gravity = false, const std::vector<double>& extra = {}) {
  std::vector<double> values = {time, dt, t.kinetic, t.internal, t.boundary, t.total};
  if (gravity) values.insert(values.begin() + 4, t.potential);
  for (int k = 0; k < D; ++k) values.push_back(t.momentum[k]);
  for (int k = 0; k < angular_components<D>; ++k) values.push_back(t.angular_momentum[k]);
  values.push_back(t.mass);
  values.push_back(mean_neighbours);
  values.insert(values.end(), extra.begin(), extra.end());
  char field[40];
  std::snprintf(field, sizeof field, "%8ld", step);
  std::string line = field;
  for (const double value : values) {
    std::snprintf(field, sizeof field, " %24.16e", value);
    line += field;
  }
  return line + "\n";
}

/// The open statistics file; only rank 0 holds a stream, every call is collective so that a
/// failure (a full disk) is the same io_error on every rank. Rows go to `<path>.partial`, renamed
/// over `<path>` by commit() once the run succeeded: a failed run never replaces an earlier file.
class statistics_log {
 public:
  bool is_open() const { return open_; }
  const std::string& path() const { return path_; }

  /// A new run (`restart_step` empty) starts `<path>.partial` with `header`. A restart at step N
  /// continues the file of the run it continues (the `.partial` an interrupted run left, else
  /// `path`): its header is kept and its rows after step N are dropped first (the earlier run
  /// may have gone past its checkpoint), when the column line is this run's; without a file, a
  /// new one is started with `header`.
  void open(const std::string& path, const std::string& header, std::optional<long> restart_step) {
    flecsi_lite::io::agree(flecsi_lite::runtime::communicator(), [&] {
      if (flecsi_lite::runtime::rank() != 0) return;
      std::string kept = header;
      if (restart_step) {
        const auto regular = [](const std::string& name) {
          return std::filesystem::is_regular_file(std::filesystem::symlink_status(name));
        };
        const std::string partial = path + ".partial";
        if (regular(partial))
          kept = rows_up_to(partial, header, *restart_step);
        else if (regular(path))
          kept = rows_up_to(path, header, *restart_step);
        kept += restart_mark + std::to_string(*restart_step) + "\n";
      }
      flecsi_lite::io::write_text_file_aside(path, kept, "statistics_file");
      out_.open(path + ".partial", std::ios::app);
      if (!out_) throw flecsi_lite::io::file_error("cannot append to the statistics_file '" + path + ".partial'");
    });
    path_ = path;
    open_ = true;
  }

  /// Once the run succeeded: `<path>.partial`, complete, replaces `path`. Collective.
  void commit() {
    if (!open_) return;
    flecsi_lite::io::agree(flecsi_lite::runtime::communicator(), [&] {
      if (flecsi_lite::runtime::rank() != 0) return;
      out_.close();
      if (!out_) throw flecsi_lite::io::file_error("cannot write to the statistics_file '" + path_ + ".partial'");
      flecsi_lite::io::commit_text_file(path_, "statistics_file");
    });
    open_ = false;
  }

  /// Appends one row and flushes it (a crash keeps every row written). Collective.
  void write(const std::string& line) {
    if (!open_) return;
    flecsi_lite::io::agree(flecsi_lite::runtime::communicator(), [&] {
      if (flecsi_lite::runtime::rank() != 0) return;
      if (!(out_ << line).flush())
        throw flecsi_lite::io::file_error("cannot write to the statistics_file '" + path_ + "'");
    });
  }

 private:
  /// The text of `path` without its rows after `step`; throws unless its column line is `header`'s.
  static std::string rows_up_to(const std::string& path, const std::string& header, long step) {
    const auto column_line = [](const std::string& text) {
      std::istringstream lines(text);
      std::string line, last;
      // The marks of earlier restarts are no header lines (a restart may find nothing but them).
      while (std::getline(lines, line) && !line.empty() && line[0] == '#')
        if (line.compare(0, restart_mark.size(), restart_mark) != 0) last = line;
      return last;
    };
    std::ifstream in(path);
    std::ostringstream whole;
    whole << in.rdbuf();
    if (!in && !in.eof()) throw flecsi_lite::io::file_error("cannot read the statistics_file '" + path + "'");
    const std::string text = whole.str();
    if (column_line(text) != column_line(header))
      throw flecsi_lite::io::file_error("statistics_file '" + path + "' has other columns than this run ('" +
                                        column_line(text) + "'): set statistics_file to another name");
    std::istringstream lines(text);
    std::string kept;
    for (std::string line; std::getline(lines, line);) {
      if (!line.empty() && line[0] != '#' && row_step(path, line) > step) break;  // rows are in step order
      kept += line + "\n";
    }
    return kept;
  }

  static long row_step(const std::string& path, const std::string& line) {
    std::istringstream in(line);
    long step = 0;
    if (!(in >> step))
      throw flecsi_lite::io::file_error("statistics_file '" + path + "': a row that is not a step: '" + line + "'");
    return step;
  }

  static inline const std::string restart_mark = "# restarted at step ";
  std::string path_;
  bool open_ = false;
  std::ofstream out_;  // rank 0 only
};

}  // namespace flecsph::sph
