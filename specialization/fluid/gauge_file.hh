// The gauge file (key gauge_file): comma-separated rows "step,t,front_x,p_1,vx_1,vy_1,..." under
// '#' header lines, one row per gauge_every steps, each flushed (a crash keeps what was written).
// A restart at step N continues the file of the run it continues: its header is kept, its rows
// after step N are dropped first (that run may have gone past its checkpoint) and a line
// "# restarted at step N" marks the place, so the rows are those of an uninterrupted run. Only
// rank 0 holds the stream; every call is collective, so a failure is the same error on all ranks.
#pragma once

#include "flecsi_lite/io.hh"
#include "flecsi_lite/runtime.hh"

#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>

namespace flecsph::fluid {

class gauge_file {
 public:
  /// `header`: '#' lines, the last one the columns. A new run (`restart_step` empty) replaces
  /// `path`; a restart keeps its rows up to the step, or starts a new file when there is none.
  void open(const std::string& path, const std::string& header, std::optional<long> restart_step) {
    flecsi_lite::io::agree(flecsi_lite::runtime::communicator(), [&] {
      if (flecsi_lite::runtime::rank() != 0) return;
      std::string kept = header;
      if (restart_step) {
        if (std::filesystem::is_regular_file(std::filesystem::symlink_status(path)))
          kept = rows_up_to(path, header, *restart_step);
        kept += restart_mark + std::to_string(*restart_step) + "\n";
      }
      flecsi_lite::io::write_text_file(path, kept, "gauge_file");
      out_.open(path, std::ios::app);
      if (!out_) throw flecsi_lite::io::file_error("cannot append to the gauge_file '" + path + "'");
    });
    path_ = path;
  }

  bool is_open() const { return !path_.empty(); }

  /// Appends one row (collective).
  void write(const std::string& row) {
    flecsi_lite::io::agree(flecsi_lite::runtime::communicator(), [&] {
      if (flecsi_lite::runtime::rank() != 0) return;
      if (!(out_ << row << '\n').flush())
        throw flecsi_lite::io::file_error("cannot write to the gauge_file '" + path_ + "'");
    });
  }

 private:
  static std::string column_line(const std::string& text) {
    std::istringstream lines(text);
    std::string line, last;
    while (std::getline(lines, line) && !line.empty() && line[0] == '#')
      if (line.compare(0, restart_mark.size(), restart_mark) != 0) last = line;
    return last;
  }

  /// The text of `path` without its rows after `step`; throws unless its columns are `header`'s.
  static std::string rows_up_to(const std::string& path, const std::string& header, long step) {
    std::ifstream in(path);
    std::ostringstream whole;
    whole << in.rdbuf();
    if (!in && !in.eof()) throw flecsi_lite::io::file_error("cannot read the gauge_file '" + path + "'");
    const std::string text = whole.str();
    if (column_line(text) != column_line(header))
      throw flecsi_lite::io::file_error("gauge_file '" + path + "' has other columns ('" + column_line(text) +
                                        "') than this run ('" + column_line(header) +
                                        "'): set gauge_file to another name");
    std::istringstream lines(text);
    std::string kept;
    for (std::string line; std::getline(lines, line);) {
      if (!line.empty() && line[0] != '#') {
        std::istringstream row(line);
        long row_step = 0;
        if (!(row >> row_step))
          throw flecsi_lite::io::file_error("gauge_file '" + path + "': a row that is not a step: '" + line + "'");
        if (row_step > step) break;  // rows are in step order
      }
      kept += line + "\n";
    }
    return kept;
  }

  static inline const std::string restart_mark = "# restarted at step ";
  std::string path_;
  std::ofstream out_;  // rank 0 only
};

}  // namespace flecsph::fluid
